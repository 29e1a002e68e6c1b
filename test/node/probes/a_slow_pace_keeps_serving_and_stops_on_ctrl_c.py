"""The ROS side of test_node_slow_pace.py::test_a_slow_pace_keeps_serving_and_stops_on_ctrl_c, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, time, rospy
from std_srvs.srv import Empty
rospy.wait_for_service('/gazebo/reset_world', 20)
call = rospy.ServiceProxy('/gazebo/reset_world', Empty)
call()
worst = 0.0
for _ in range(3):
    start = time.monotonic()
    call()
    worst = max(worst, time.monotonic() - start)
print(json.dumps(worst))
