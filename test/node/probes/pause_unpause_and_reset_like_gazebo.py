"""The ROS side of test_ros_plant.py::test_pause_unpause_and_reset_like_gazebo, a rospy program the test runs
against its own master (ros.probe); it prints one JSON value on its last line."""
import json, time, rospy
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty
rospy.init_node('probe', anonymous=True)
stamps = []
rospy.Subscriber('/clock', Clock, lambda m: stamps.append(m.clock.to_sec()))
def call(name):
    rospy.wait_for_service(name, 10)
    rospy.ServiceProxy(name, Empty)()
def settle(seconds):
    time.sleep(seconds)
    return len(stamps)
settle(1.0)
call('/gazebo/pause_physics')
n = settle(0.1)
paused_at = stamps[-1]
during_pause = settle(0.5) - n
call('/gazebo/unpause_physics')
end = time.time() + 20  # generous: a loaded machine may take a while to publish again
while len(stamps) <= n and time.time() < end:
    time.sleep(0.01)
resumed = stamps[n]
call('/gazebo/reset_simulation')
settle(0.3)
print(json.dumps(dict(paused_at=paused_at, during_pause=during_pause, resumed=resumed, after_reset=stamps[-1])))
