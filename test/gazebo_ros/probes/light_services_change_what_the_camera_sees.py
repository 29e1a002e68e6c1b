"""The ROS side of test_light_services.py, a rospy program the test runs against its own master (ros.probe):
the camera's mean grey level after each light service call, from the first frame stamped after it;
it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
import numpy as np
from sensor_msgs.msg import Image
from std_msgs.msg import ColorRGBA
frames = []
rospy.Subscriber('/eye/image_raw', Image, lambda m: frames.append(m), queue_size=100)
world = srv('get_world_properties', GetWorldProperties)
get_light = srv('get_light_properties', GetLightProperties)
set_light = srv('set_light_properties', SetLightProperties)
delete_light = srv('delete_light', DeleteLight)


def mean_after():
    """The mean grey of the first frame stamped after now (in simulated time)."""
    now = world().sim_time
    deadline = time.time() + 30
    while time.time() < deadline:
        later = [f for f in list(frames) if f.header.stamp.to_sec() > now]
        if later:
            pixels = np.frombuffer(later[0].data, dtype=np.uint8).reshape(later[0].height, later[0].width, 3)
            return float(pixels.astype(float).mean())
        time.sleep(0.02)
    raise RuntimeError('no frame after %g s' % now)


def props(name):
    p = get_light(name)
    return [result(p), [p.diffuse.r, p.diffuse.g, p.diffuse.b, p.diffuse.a],
            [p.attenuation_constant, p.attenuation_linear, p.attenuation_quadratic]]


def at(x, y, z):
    return pose(x, y, z)


out['lamp'] = props('lamp')
out['sun'] = props('sun')
out['unknown'] = props('nolamp')
out['start'] = mean_after()
# brighter lamp, same place
out['set_lamp'] = result(set_light('lamp', False, ColorRGBA(1, 1, 1, 1), ColorRGBA(), 1.0, 0.5, 0.0,
                                   Vector3(0, 0, -1), at(0, 0, 1)))
out['brighter'] = mean_after()
out['lamp_after'] = props('lamp')
# an attenuation that lights nothing is refused, the light as it was
out['dark_attenuation'] = result(set_light('lamp', False, ColorRGBA(1, 1, 1, 1), ColorRGBA(), 0.0, 0.0, 0.0,
                                           Vector3(0, 0, -1), at(0, 0, 1)))
out['set_unknown'] = result(set_light('nolamp', False, ColorRGBA(1, 1, 1, 1), ColorRGBA(), 1.0, 0.0, 0.0,
                                      Vector3(0, 0, -1), at(0, 0, 1)))
out['delete_lamp'] = result(delete_light('lamp'))
out['without_lamp'] = mean_after()
out['delete_again'] = result(delete_light('lamp'))
# the sun slanted 45 degrees: the floor gets cos 45 of its light
out['slant_sun'] = result(set_light('sun', True, ColorRGBA(0.8, 0.8, 0.8, 1), ColorRGBA(), 0.9, 0.01, 0.001,
                                    Vector3(1, 0, -1), Pose()))
out['slanted'] = mean_after()
out['delete_sun'] = result(delete_light('sun'))
out['ambient_only'] = mean_after()
out['sun_gone'] = props('sun')
print(json.dumps(out))
