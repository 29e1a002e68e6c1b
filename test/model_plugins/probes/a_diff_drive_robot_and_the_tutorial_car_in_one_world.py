"""The ROS side of test_diff_drive_ros.py::test_a_diff_drive_robot_and_the_tutorial_car_in_one_world, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy, tf2_ros
from gazebo_msgs.msg import ModelStates
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan
from ros_harness import connected_publisher
rospy.init_node('probe')
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
def positions():
    states = rospy.wait_for_message('/gazebo/model_states', ModelStates, 10)
    return {name: [pose.position.x, pose.position.y] for name, pose in zip(states.name, states.pose)}
scan = rospy.wait_for_message('/tb3/scan', LaserScan, 30)
before = positions()
car, tb3 = connected_publisher('/tianracer/cmd_vel', Twist, queue_size=1), connected_publisher('/tb3/cmd_vel', Twist, queue_size=1)
fast, slow = Twist(), Twist()
fast.linear.x, slow.linear.x = 0.5, 0.2
for _ in range(25):
    car.publish(fast)
    tb3.publish(slow)
    rospy.sleep(0.1)
after = positions()
tf = buffer.lookup_transform('tb3/odom', 'tb3/base_footprint', rospy.Time(0), rospy.Duration(5))
print(json.dumps({'before': before, 'after': after, 'scan_frame': scan.header.frame_id,
                  'scan_hits': sum(1 for r in scan.ranges if r < 3.5), 'tb3_tf_x': tf.transform.translation.x}))
