"""The ROS side of
test_gazebo_ros.py::test_step_physics_runs_that_many_iterations_while_paused_and_scene_contacts_has_the_tyres,
a rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last
line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
from gazebo_msgs.msg import ContactsState
from rosgraph_msgs.msg import Clock
from std_msgs.msg import UInt32
step = connected_publisher('/gazebo/step_physics', UInt32, queue_size=10)
clocks = []
contacts = []
subscribers = [rospy.Subscriber('/clock', Clock, lambda m: clocks.append(m.clock.to_nsec())),
               rospy.Subscriber('/gazebo/scene_contacts', ContactsState, lambda m: contacts.append(m))]
while any(s.get_num_connections() == 0 for s in subscribers):  # paused: nothing on either until a step
    time.sleep(0.05)
def stepped(n):
    count = len(clocks)
    step.publish(UInt32(n))
    deadline = time.time() + 20
    while time.time() < deadline and (len(clocks) == count or clocks[-1] < (clocks[count - 1] if count else 0) + n * 1000000):
        time.sleep(0.01)
    time.sleep(0.3)
    return clocks[-1] if clocks else None
out['start'] = stepped(1)
out['after_7'] = stepped(7)
out['after_2000'] = stepped(2000)
time.sleep(0.5)
out['still'] = clocks[-1]
out['paused'] = srv('get_physics_properties', GetPhysicsProperties)().pause
out['contacts'] = [(s.collision1_name, s.collision2_name, s.contact_positions[0].z, s.contact_normals[0].z,
                    s.total_wrench.force.z, m.header.frame_id) for m in contacts[-1:] for s in m.states]
out['contact_messages'] = len(contacts)
print(json.dumps(out))
