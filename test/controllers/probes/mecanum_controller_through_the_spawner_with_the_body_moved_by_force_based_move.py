"""The ROS side of
test_mecanum_drive_controller_ros.py::test_mecanum_controller_through_the_spawner_with_the_body_moved_by_force_based_move,
a rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last
line."""
import json, rospy, tf2_ros
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState
from ros_harness import connected_publisher
rospy.init_node('probe')
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
to_controller = connected_publisher('/mecanum_bot/mecanum_controller/cmd_vel', Twist, queue_size=1)
to_body = connected_publisher('/cmd_vel', Twist, queue_size=1)
state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
start = state('mecanum_bot', '').pose.position
twist = Twist()
twist.linear.y, twist.angular.z = 0.3, 0.2
# Read while the commands still come: 0.25 s after the last one the controller brakes the wheels.
latest = {}
rospy.Subscriber('/mecanum_bot/mecanum_controller/odom', Odometry, lambda m: latest.__setitem__('odom', m))
rospy.Subscriber('/mecanum_bot/joint_states', JointState, lambda m: latest.__setitem__('joints', m))
for _ in range(30):
    to_controller.publish(twist)
    to_body.publish(twist)
    rospy.sleep(0.1)
odom, joints = latest['odom'], latest['joints']
tf = buffer.lookup_transform('odom', 'base_footprint', rospy.Time(0), rospy.Duration(5)).transform.translation
end = state('mecanum_bot', '').pose.position
t = odom.twist.twist
print(json.dumps({'frames': [odom.header.frame_id, odom.child_frame_id], 'twist': [t.linear.x, t.linear.y, t.angular.z],
                  'odom_y': odom.pose.pose.position.y, 'tf_y': tf.y, 'moved_y': end.y - start.y,
                  'speeds': dict(zip(joints.name, joints.velocity))}))
