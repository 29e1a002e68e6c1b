"""The ROS side of test_range_ros.py::test_range_sensor_reports_the_nearest_ray_to_a_wall, a rospy program the
test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Range
from ros_harness import connected_publisher
rospy.init_node('probe')
before = rospy.wait_for_message('/range/fr', Range, 30)
pub = connected_publisher('/cmd_vel', Twist, queue_size=1)
twist = Twist()
twist.linear.x = 0.2
for _ in range(10):
    pub.publish(twist)
    rospy.sleep(0.1)
pub.publish(Twist())
rospy.sleep(0.5)
after = rospy.wait_for_message('/range/fr', Range, 10)
x = rospy.wait_for_message('/odom', Odometry, 10).pose.pose.position.x
print(json.dumps({'frame': before.header.frame_id, 'radiation': before.radiation_type,
                  'fov': before.field_of_view, 'limits': [before.min_range, before.max_range],
                  'before': before.range, 'after': after.range, 'x': x}))
