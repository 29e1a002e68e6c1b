"""The ROS side of test_spawn_delete_memory.py: argv[1] cycles of each of an SDF and a URDF model with
a camera, a laser and a p3d plugin, spawned through /gazebo/spawn_sdf_model (spawn_urdf_model), each
time until its camera, laser and p3d have published once to this probe's subscribers (so the sensors
have run), then deleted; the node's resident memory (argv[2] is its pid) after each tenth of the
cycles. Prints one JSON value on its last line."""
import sys
import threading

from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Image, LaserScan

CYCLES, NODE_PID = int(sys.argv[1]), int(sys.argv[2])
NS = '/cycled'
PLUGINS = {
    'camera': '<plugin name="camera_plugin" filename="libgazebo_ros_camera.so"><robotNamespace>%s</robotNamespace>'
              '<cameraName>camera</cameraName><frameName>body</frameName></plugin>' % NS,
    'laser': '<plugin name="laser_plugin" filename="libgazebo_ros_laser.so"><robotNamespace>%s</robotNamespace>'
             '<topicName>scan</topicName><frameName>body</frameName></plugin>' % NS,
    'p3d': '<plugin name="p3d_plugin" filename="libgazebo_ros_p3d.so"><robotNamespace>%s</robotNamespace>'
           '<bodyName>body</bodyName><topicName>truth</topicName><updateRate>50</updateRate></plugin>' % NS,
}
SENSORS = ('<sensor name="camera" type="camera"><update_rate>30</update_rate><camera><horizontal_fov>1.0</horizontal_fov>'
           '<image><width>64</width><height>48</height></image><clip><near>0.05</near><far>20</far></clip></camera>%s</sensor>'
           '<sensor name="laser" type="ray"><update_rate>20</update_rate><ray><scan><horizontal><samples>90</samples>'
           '<min_angle>-1.5</min_angle><max_angle>1.5</max_angle></horizontal></scan><range><min>0.1</min><max>10</max>'
           '</range></ray>%s</sensor>' % (PLUGINS['camera'], PLUGINS['laser']))
BOX = '<box size="0.3 0.3 0.2"/>'
SDF = ('<?xml version="1.0"?><sdf version="1.6"><model name="cycled"><link name="body">'
       '<inertial><mass>2</mass><inertia><ixx>0.02</ixx><iyy>0.02</iyy><izz>0.03</izz></inertia></inertial>'
       '<collision name="shell"><geometry><box><size>0.3 0.3 0.2</size></box></geometry></collision>'
       '<visual name="look"><geometry><box><size>0.3 0.3 0.2</size></box></geometry></visual>%s</link>%s</model></sdf>'
       % (SENSORS, PLUGINS['p3d']))
URDF = ('<?xml version="1.0"?><robot name="cycled"><link name="body"><inertial><mass value="2"/>'
        '<inertia ixx="0.02" iyy="0.02" izz="0.03" ixy="0" ixz="0" iyz="0"/></inertial>'
        '<collision><geometry>%s</geometry></collision><visual><geometry>%s</geometry></visual></link>'
        '<gazebo reference="body">%s</gazebo><gazebo>%s</gazebo></robot>' % (BOX, BOX, SENSORS, PLUGINS['p3d']))

heard = {}
arrived = threading.Condition()


def hear(topic):
    def callback(_):
        with arrived:
            heard[topic] = True
            arrived.notify_all()
    return callback


TOPICS = {NS + '/camera/image_raw': Image, NS + '/scan': LaserScan, NS + '/truth': Odometry}
for topic, kind in TOPICS.items():
    rospy.Subscriber(topic, kind, hear(topic), queue_size=1)


def resident_kb():
    with open('/proc/%d/status' % NODE_PID) as status:
        return next(int(line.split()[1]) for line in status if line.startswith('VmRSS'))


spawners = {'sdf': srv('spawn_sdf_model', SpawnModel), 'urdf': srv('spawn_urdf_model', SpawnModel)}
delete = srv('delete_model', DeleteModel)
out.update(cycles=CYCLES, failures=[], unheard=[], kb={})
for kind, text in (('sdf', SDF), ('urdf', URDF)):
    for cycle in range(CYCLES):
        with arrived:
            heard.clear()
        reply = spawners[kind]('cycled', text, '', pose(0, 0, 0.1), '')
        if not reply.success:
            out['failures'].append([kind, cycle, reply.status_message])
            break
        with arrived:
            arrived.wait_for(lambda: len(heard) == 3, timeout=5)
            # A topic not heard in 5 s: rospy did not connect to the new publisher of a topic whose
            # last publisher (the deleted model's, of the same node) it just dropped (counted).
            if len(heard) < 3:
                out['unheard'].append([kind, cycle, sorted(set(TOPICS) - set(heard))])
        delete('cycled')
        if (cycle + 1) % max(1, CYCLES // 10) == 0:
            out['kb'].setdefault(kind, []).append(resident_kb())
print(json.dumps(out))
