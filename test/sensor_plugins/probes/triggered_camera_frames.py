"""The ROS side of test_triggered_camera_ros.py, a rospy program the test runs against its own master
(ros.probe): counts cam/image_raw frames with no trigger, after one std_msgs/Empty on
cam/image_trigger, and after two sent 10 ms apart, each count taken 1.5 s (wall) after the last
trigger; also who subscribes the trigger topic. Prints one JSON value on its last line."""
import json, time, rospy, rosgraph
from sensor_msgs.msg import Image
from std_msgs.msg import Empty
rospy.init_node('probe')
frames = []
rospy.Subscriber('/cam/image_raw', Image, lambda m: frames.append((m.header.stamp.to_sec(), rospy.get_time())))
trigger = rospy.Publisher('/cam/image_trigger', Empty, queue_size=2)
deadline = time.time() + 30
while trigger.get_num_connections() == 0 and time.time() < deadline:
    time.sleep(0.05)
time.sleep(1.5)
counts = {'untriggered': len(frames)}
_, subscribers, _ = rosgraph.Master('/probe').getSystemState()
counts['trigger_subscribers'] = sorted(n for topic, nodes in subscribers if topic == '/cam/image_trigger' for n in nodes)
trigger.publish(Empty())
time.sleep(1.5)
counts['after_one'] = len(frames)
trigger.publish(Empty())
time.sleep(0.01)
trigger.publish(Empty())
time.sleep(1.5)
counts['after_two_more'] = len(frames)
counts['stamp_lag'] = max(received - stamp for stamp, received in frames) if frames else None
print(json.dumps(counts))
