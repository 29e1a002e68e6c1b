"""The ROS side of test_viewer.py::test_the_cars_drawn_pose_follows_model_states_as_it_drives, a rospy program
the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from std_msgs.msg import Float64
from gazebo_msgs.msg import ModelStates
rospy.init_node('driver', anonymous=True)
wheels = [rospy.Publisher('/tianracer/%s/command' % c, Float64, queue_size=1)
          for c in ('rear_left_velocity_controller', 'rear_right_velocity_controller')]
rospy.sleep(1.0)
end = rospy.Time.now() + rospy.Duration(1.5)
while rospy.Time.now() < end:
    for w in wheels:
        w.publish(12.0)
    rospy.sleep(0.05)
for _ in range(20):
    for w in wheels:
        w.publish(0.0)
    rospy.sleep(0.05)
rospy.sleep(1.0)
states = rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=10)
p = states.pose[states.name.index('tianracer')].position
print(json.dumps([p.x, p.y]))
