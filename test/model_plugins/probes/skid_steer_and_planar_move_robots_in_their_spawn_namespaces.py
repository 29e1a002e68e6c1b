"""The ROS side of
test_skid_steer_and_planar_move_ros.py::test_skid_steer_and_planar_move_robots_in_their_spawn_namespaces, a
rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy, tf2_ros
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu, JointState, NavSatFix
from ros_harness import connected_publisher
rospy.init_node('probe')
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
skid = connected_publisher('/skid_bot/cmd_vel', Twist, queue_size=1)
planar = connected_publisher('/planar_bot/cmd_vel', Twist, queue_size=1)
forward, sideways = Twist(), Twist()
forward.linear.x = 0.3
sideways.linear.y = 0.2
rospy.wait_for_message('/skid_bot/odom', Odometry, 30)
skid_odoms = []
rospy.Subscriber('/skid_bot/odom', Odometry, skid_odoms.append)
for _ in range(20):
    skid.publish(forward)
    planar.publish(sideways)
    rospy.sleep(0.1)
skid_odom = rospy.wait_for_message('/skid_bot/odom', Odometry, 10)
planar_odom = rospy.wait_for_message('/planar_bot/odom', Odometry, 10)
joints = rospy.wait_for_message('/skid_bot/joint_states', JointState, 10)
fix = rospy.wait_for_message('/navsat/fix', NavSatFix, 10)
rospy.sleep(0.2)
# the skid bot still drives (skid_steer_drive has no timeout): compare the fix with the odometry of its time
odom_at_fix = min(skid_odoms, key=lambda odom: abs((odom.header.stamp - fix.header.stamp).to_sec()))
imu = rospy.wait_for_message('/imu/data', Imu, 10)
# hector's IMU services: set_accel_bias shows on the bias topic, calibrate answers
from geometry_msgs.msg import Vector3
from hector_gazebo_plugins.srv import SetBias
from std_srvs.srv import Empty
rospy.ServiceProxy('/imu/data/set_accel_bias', SetBias)(Vector3(0.4, 0.0, 0.0))
rospy.ServiceProxy('/imu/data/calibrate', Empty)()
rospy.sleep(0.1)
accel_bias = rospy.wait_for_message('/imu/data/bias', Imu, 10).linear_acceleration.x
# at the odometry's stamp: planar_move has no command timeout, the bot still slides
tf = buffer.lookup_transform('odom', 'planar_base', planar_odom.header.stamp, rospy.Duration(5))
print(json.dumps({
    'skid': [skid_odom.header.frame_id, skid_odom.child_frame_id, skid_odom.twist.twist.linear.x,
             skid_odom.pose.pose.position.x, skid_odom.pose.covariance[35]],
    'planar': [planar_odom.child_frame_id, planar_odom.twist.twist.linear.y, planar_odom.pose.pose.position.y],
    'tf_y': tf.transform.translation.y,
    'joints': list(joints.name), 'wheel_speeds': list(joints.velocity),
    'fix': [fix.header.frame_id, fix.latitude, fix.position_covariance_type, fix.position_covariance[0]],
    'x_at_fix': odom_at_fix.pose.pose.position.x,
    'imu': [imu.header.frame_id, imu.linear_acceleration.z, imu.angular_velocity_covariance[0]],
    'accel_bias': accel_bias}))
