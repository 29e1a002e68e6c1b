"""The node on a machine with no EGL driver at all (glvnd's libEGL given no vendor file: what a
machine without Mesa's libegl-mesa0 or a GPU's driver has): it starts, says once on /rosout that
the cameras are off and why, publishes no camera image, and everything else runs: the car spawns,
the tutorial's controllers start and turn a wheel, the lidar scans, /clock advances."""
import pytest

from ros_harness import tianracer_plant
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros

NS = '/tianracer'


@pytest.mark.slow
def test_without_egl_the_node_runs_with_its_cameras_off(ros, urdf_file):
    ros.env['__EGL_VENDOR_LIBRARY_FILENAMES'] = '/nonexistent/egl_vendor.json'
    plant = tianracer_plant(ros, urdf_file)
    ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=' + NS, *TUTORIAL_CONTROLLERS], 'spawner')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS), namespace=NS)
    seen = ros.python("""
        import json, time, rospy
        from rosgraph_msgs.msg import Clock, Log
        from sensor_msgs.msg import Image, JointState, LaserScan
        from std_msgs.msg import Float64
        from ros_harness import connected_publisher
        rospy.init_node('probe')
        said = []
        rospy.Subscriber('/rosout_agg', Log, lambda m: said.append(m.msg) if 'cameras:' in m.msg else None)
        images = []
        for topic in ('/camera/image_raw', '/depth_camera/rgb/image_raw', '/depth_camera/depth/image_raw'):
            rospy.Subscriber(topic, Image, lambda m, t=topic: images.append(t))
        scan = rospy.wait_for_message('/scan', LaserScan, 20)
        first = rospy.wait_for_message('/clock', Clock, 10).clock.to_sec()
        command = connected_publisher('%s/rear_left_velocity_controller/command', Float64, queue_size=1, latch=True)
        command.publish(Float64(8.0))
        deadline = time.monotonic() + 20
        wheel = 0.0
        while time.monotonic() < deadline and abs(wheel - 8.0) > 0.2:
            state = rospy.wait_for_message('%s/joint_states', JointState, 10)
            wheel = dict(zip(state.name, state.velocity))['left_rear_wheel_joint']
        rospy.sleep(2.0)  # sim time: the cameras' rates would have given frames by now
        print(json.dumps({'said': said, 'images': images, 'ranges': len(scan.ranges), 'wheel': wheel,
                          'clock': rospy.wait_for_message('/clock', Clock, 10).clock.to_sec() - first}))
    """ % (NS, NS), timeout=90)
    log = plant.log()
    assert 'cameras: off, no OpenGL (' in log and 'every other sensor runs' in log, log[-3000:]
    assert log.count('cameras: off') == 1, 'said once'
    assert seen['images'] == [], 'no camera image'
    assert seen['ranges'] == 1081
    assert seen['wheel'] == pytest.approx(8.0, abs=0.2)
    assert seen['clock'] > 2.0
