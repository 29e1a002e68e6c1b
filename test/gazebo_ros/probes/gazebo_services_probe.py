"""The start the gazebo_ros probes share (`from gazebo_services_probe import *`): a rospy node, gazebo_msgs' services
and messages, srv() for a /gazebo service once it is up, pose(), result() of a reply, and `out`, the
JSON object a probe prints."""
import json, math, time, rospy
from gazebo_msgs.msg import LinkState, ModelState, ModelStates, LinkStates
from gazebo_msgs.srv import *
from geometry_msgs.msg import Point, Pose, Twist, Vector3, Wrench
from std_srvs.srv import Empty
from ros_harness import connected_publisher
rospy.init_node('gazebo_probe', anonymous=True)
def srv(name, kind):
    rospy.wait_for_service('/gazebo/' + name, 30)
    return rospy.ServiceProxy('/gazebo/' + name, kind)
def pose(x=0.0, y=0.0, z=0.0, yaw=0.0):
    p = Pose()
    p.position.x, p.position.y, p.position.z = x, y, z
    p.orientation.z, p.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return p
def result(r):
    return [bool(r.success), r.status_message]
out = {}
