"""The ROS side of test_publishing_threads.py: with the plant paused and the diff_bot spawned, drives
it on a circle (/cmd_vel, delivered before the simulation starts), unpauses and records /odom and
/scan by their stamps until `until` s of simulated time; prints one JSON value on its last line."""
import json, sys, time, rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty
until = float(sys.argv[1])
rospy.init_node('probe', anonymous=True)
odom, scans, clock = {}, {}, [0.0]
def stamp(m):
    return '%d.%09d' % (m.header.stamp.secs, m.header.stamp.nsecs)
def on_odom(m):
    p, q, v = m.pose.pose.position, m.pose.pose.orientation, m.twist.twist
    odom[stamp(m)] = [p.x, p.y, p.z, q.x, q.y, q.z, q.w, v.linear.x, v.angular.z]
subscribers = [rospy.Subscriber('/odom', Odometry, on_odom),
               rospy.Subscriber('/scan', LaserScan, lambda m: scans.__setitem__(stamp(m), list(m.ranges))),
               rospy.Subscriber('/clock', Clock, lambda m: clock.__setitem__(0, m.clock.to_sec()))]
drive = rospy.Publisher('/cmd_vel', Twist, queue_size=1, latch=True)
twist = Twist()
twist.linear.x, twist.angular.z = 0.2, 0.8
drive.publish(twist)
deadline = time.time() + 20
while time.time() < deadline and (drive.get_num_connections() < 1 or
                                  any(s.get_num_connections() < 1 for s in subscribers)):
    time.sleep(0.05)
time.sleep(1.0)  # the command goes to the paused simulation thread, which serves its queue between waits
rospy.wait_for_service('/gazebo/unpause_physics', 10)
rospy.ServiceProxy('/gazebo/unpause_physics', Empty)()
while time.time() < deadline + 60 and clock[0] < until:
    time.sleep(0.05)
time.sleep(0.5)  # the last messages on their way
print(json.dumps(dict(odom=odom, scans=scans)))
