"""The first message of each TOPIC stamped at or after SECONDS of simulated time, summarised for
comparison (test_sdf_model_sensors_ros.py):

    messages_after.py SECONDS TOPIC...

prints {TOPIC: {'type', 'frame', and per type: LaserScan ranges; Range range, radiation and fov; Image
width, height, encoding and mean byte; CameraInfo K; Imu orientation and acceleration; Odometry child and position}} as one JSON
object on its last line."""
import json, rospy, rostopic, sys, time
after = float(sys.argv[1])
rospy.init_node('probe', anonymous=True)
first = {}


def summary(m):
    out = {'type': m._type, 'frame': m.header.frame_id}
    if m._type == 'sensor_msgs/LaserScan':
        out['ranges'] = [r if r == r and r != float('inf') else None for r in m.ranges]
    elif m._type == 'sensor_msgs/Range':
        out.update(range=m.range, radiation=m.radiation_type, fov=m.field_of_view)
    elif m._type == 'sensor_msgs/Image':
        data = bytearray(m.data)
        out.update(width=m.width, height=m.height, encoding=m.encoding, mean=sum(data) / max(1, len(data)))
    elif m._type == 'sensor_msgs/CameraInfo':
        out['K'] = list(m.K)
    elif m._type == 'sensor_msgs/Imu':
        o, a = m.orientation, m.linear_acceleration
        out.update(orientation=[o.x, o.y, o.z, o.w], acceleration=[a.x, a.y, a.z])
    elif m._type == 'nav_msgs/Odometry':
        p = m.pose.pose.position
        out.update(child=m.child_frame_id, position=[p.x, p.y, p.z])
    return out


def keep(topic):
    def callback(m):
        if topic not in first and m.header.stamp.to_sec() >= after:
            first[topic] = summary(m)
    return callback


subscribers = []
for topic in sys.argv[2:]:
    cls, _, _ = rostopic.get_topic_class(topic, blocking=True)
    subscribers.append(rospy.Subscriber(topic, cls, keep(topic)))
deadline = time.time() + 60
while len(first) < len(sys.argv) - 2 and time.time() < deadline:
    time.sleep(0.05)
missing = [t for t in sys.argv[2:] if t not in first]
if missing:
    sys.exit('no message stamped after %g s on %s' % (after, ', '.join(missing)))
print(json.dumps(first))
