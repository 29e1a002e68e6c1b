"""The ROS side of test_no_opengl_ros.py::test_without_egl_the_node_runs_with_its_cameras_off, a rospy program the
test runs against its own master (ros.probe) with the car's namespace; it prints one JSON value on its last line."""
import json, sys, time, rospy
from rosgraph_msgs.msg import Clock, Log
from sensor_msgs.msg import Image, JointState, LaserScan
from std_msgs.msg import Float64
from ros_harness import connected_publisher
rospy.init_node('probe')
NS = sys.argv[1]
said = []
rospy.Subscriber('/rosout_agg', Log, lambda m: said.append(m.msg) if 'cameras:' in m.msg else None)
images = []
for topic in ('/camera/image_raw', '/depth_camera/rgb/image_raw', '/depth_camera/depth/image_raw'):
    rospy.Subscriber(topic, Image, lambda m, t=topic: images.append(t))
scan = rospy.wait_for_message('/scan', LaserScan, 20)
first = rospy.wait_for_message('/clock', Clock, 10).clock.to_sec()
command = connected_publisher(NS + '/rear_left_velocity_controller/command', Float64, queue_size=1, latch=True)
command.publish(Float64(8.0))
deadline = time.monotonic() + 20
wheel = 0.0
while time.monotonic() < deadline and abs(wheel - 8.0) > 0.2:
    state = rospy.wait_for_message(NS + '/joint_states', JointState, 10)
    wheel = dict(zip(state.name, state.velocity))['left_rear_wheel_joint']
rospy.sleep(2.0)  # sim time: the cameras' rates would have given frames by now
print(json.dumps({'said': said, 'images': images, 'ranges': len(scan.ranges), 'wheel': wheel,
                  'clock': rospy.wait_for_message('/clock', Clock, 10).clock.to_sec() - first}))
