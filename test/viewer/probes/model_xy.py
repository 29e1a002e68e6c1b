"""The car's position in /gazebo/model_states, for test_viewer.py's teleop keys; prints [x, y] on its
last line."""
import json, rospy
from gazebo_msgs.msg import ModelStates
rospy.init_node('model_probe', anonymous=True)
states = rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=10)
p = states.pose[states.name.index('tianracer')].position
print(json.dumps([p.x, p.y]))
