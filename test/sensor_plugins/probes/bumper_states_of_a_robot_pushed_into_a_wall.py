"""The ROS side of test_bumper_ros.py::test_bumper_states_of_a_robot_pushed_into_a_wall, a rospy program the
test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from gazebo_msgs.msg import ContactsState
from geometry_msgs.msg import Wrench
from ros_harness import connected_publisher
rospy.init_node('probe')
def summary(m):
    return {'frame': m.header.frame_id, 'stamp': m.header.stamp.to_sec(),
            'states': [{'c1': s.collision1_name, 'c2': s.collision2_name, 'info': s.info,
                        'total': [s.total_wrench.force.x, s.total_wrench.force.y, s.total_wrench.force.z],
                        'sum': [sum(w.force.x for w in s.wrenches), sum(w.force.y for w in s.wrenches),
                                sum(w.force.z for w in s.wrenches)],
                        'normals': [[n.x, n.y, n.z] for n in s.contact_normals],
                        'positions': [[p.x, p.y, p.z] for p in s.contact_positions],
                        'depths': list(s.depths)} for s in m.states]}
ground = rospy.wait_for_message('/bumper_states', ContactsState, 30)
before = rospy.wait_for_message('/bumper', ContactsState, 10)
push = connected_publisher('/force', Wrench, queue_size=1, latch=True)
w = Wrench()
w.force.x = 10.0
push.publish(w)
rospy.sleep(2.0)
after = rospy.wait_for_message('/bumper', ContactsState, 10)
print(json.dumps({'ground': summary(ground), 'before': summary(before), 'after': summary(after)}))
