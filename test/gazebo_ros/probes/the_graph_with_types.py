"""The ROS graph as gazebo_ros_pkgs' ros_api_checker sees it, for test_ros_network.py: every topic
with its type and publisher count, every service with its type, this probe's own left out; once
/clock runs and after `settle` more seconds (upstream's checker waits 5 s for plugins):

    the_graph_with_types.py SETTLE

prints {"topics": {name: [type, publishers]}, "services": {name: type}} on its last line."""
import json, sys, time
import rosgraph, rospy, rosservice
settle = float(sys.argv[1])
rospy.init_node('graph_probe', anonymous=True)
deadline = time.time() + 60
while rospy.Time.now().to_sec() == 0.0 and time.time() < deadline:
    time.sleep(0.1)
time.sleep(settle)
master = rosgraph.Master(rospy.get_name())
publishers, subscribers, services = master.getSystemState()
types = dict(master.getTopicTypes())
own = rospy.get_name()
topics = {}
for name, nodes in publishers + subscribers:
    nodes = [n for n in nodes if n != own]
    if nodes or name in topics:
        count = sum(1 for t, ns in publishers if t == name for n in ns if n != own)
        topics[name] = [types.get(name, ''), count]
out = {'topics': topics,
       'services': {name: rosservice.get_service_type(name) for name, nodes in services if own not in nodes}}
print(json.dumps(out))
