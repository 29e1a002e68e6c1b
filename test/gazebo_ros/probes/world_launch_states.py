"""The ROS side of test_world_launch_files.py, a rospy program run against the test's master (ros.probe):

    world_launch_states.py [--not-before=T] SECONDS [LINK...]

waits for /gazebo/model_states, then SECONDS of simulated time more (the world runs from the node's
start: a probe that started late would otherwise see little), and until the world's clock reads T
or more (a reading at a time of the world's own, whenever the probe started), following each LINK
(a scoped link name of /gazebo/link_states) meanwhile. It prints {'time': simulated seconds,
'models': {NAME: [x, y, z, linear speed, angular speed]} of the last model_states, 'links': {LINK:
{'travel': the length of the path its origin took, 'last': [x, y, z]}}} on its last line."""
import json
import math
import sys

import rospy
from gazebo_msgs.msg import LinkStates, ModelStates

args = sys.argv[1:]
not_before = float(args.pop(0).split('=', 1)[1]) if args[0].startswith('--not-before=') else 0.0
seconds = float(args[0])
followed = args[1:]
rospy.init_node('world_launch_probe', anonymous=True)
links = {name: {'travel': 0.0, 'last': None} for name in followed}


def on_links(message):
    for name, pose in zip(message.name, message.pose):
        if name in links:
            seen = links[name]
            here = [pose.position.x, pose.position.y, pose.position.z]
            if seen['last']:
                seen['travel'] += math.dist(here, seen['last'])
            seen['last'] = here


def norm(v):
    return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)


# link_states comes every step while subscribed: the path is followed step by step
subscriber = rospy.Subscriber('/gazebo/link_states', LinkStates, on_links, queue_size=100) if followed else None
rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=60)
end = max(rospy.get_time() + seconds, not_before)
while rospy.get_time() < end and not rospy.is_shutdown():
    rospy.sleep(0.05)
states = rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=30)
if subscriber:
    subscriber.unregister()
models = {name: [pose.position.x, pose.position.y, pose.position.z, norm(twist.linear), norm(twist.angular)]
          for name, pose, twist in zip(states.name, states.pose, states.twist)}
print(json.dumps({'time': rospy.get_time(), 'models': models, 'links': links}))
