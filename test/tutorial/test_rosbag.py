"""Recording a simulation as users do (docs/ros_usage.md, "Recording a drive"): rosbag records odom, scan and
TF while the car drives, and the bag plays back, with --clock, the messages it holds."""
import pytest
import yaml

from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros

TOPICS = ['/tianracer/odom', '/scan', '/tf']

COUNT_PLAYBACK = """
    import json, os, sys, time, rospy
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import LaserScan
    rospy.init_node('playback_probe', anonymous=True)
    counts = {'odom': 0, 'scan': 0}
    rospy.Subscriber('/tianracer/odom', Odometry, lambda m: counts.__setitem__('odom', counts['odom'] + 1))
    rospy.Subscriber('/scan', LaserScan, lambda m: counts.__setitem__('scan', counts['scan'] + 1))
    # until the test says the player has exited (its file), then what is still in flight, at most 20 s
    played, end = sys.argv[1], time.time() + 20
    while time.time() < end and not os.path.exists(played):
        time.sleep(0.05)
    time.sleep(1.0)
    print(json.dumps(counts))
"""


@pytest.mark.slow
def test_a_recorded_drive_plays_back_with_its_message_counts(ros, tmp_path):
    ros.start(['roslaunch', 'tianracer_description', 'tianracer.launch', 'gui:=false'], 'tianracer_launch')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS))
    driver = ros.start(['rostopic', 'pub', '-r', '10', '/tianracer/cmd_vel', 'geometry_msgs/Twist',
                        '{linear: {x: 0.5}, angular: {z: 0.3}}'], 'driver')
    bag = str(tmp_path / 'drive.bag')
    record = ros.run(['rosbag', 'record', '-O', bag, '--duration=4'] + TOPICS, timeout=60)
    assert record.returncode == 0, record.stderr
    driver.stop()
    info = yaml.safe_load(ros.run(['rosbag', 'info', '--yaml', bag]).stdout)
    recorded = {t['topic']: t['messages'] for t in info['topics']}
    assert set(recorded) == set(TOPICS), recorded
    # 4 s of simulated time (real time factor 1): odom at 50 Hz, the lidar at 40 Hz.
    assert recorded['/tianracer/odom'] == pytest.approx(200, rel=0.15)
    assert recorded['/scan'] == pytest.approx(160, rel=0.15)

    # Playback against a master with no simulation: every recorded message arrives again.
    ros.close()
    from ros_harness import RosSystem
    (tmp_path / 'playback').mkdir()
    player_system = RosSystem(str(tmp_path / 'playback'))
    try:
        played = tmp_path / 'played'
        probe = player_system.start(['/usr/bin/python3', '-c', __import__('textwrap').dedent(COUNT_PLAYBACK), str(played)],
                                    'probe')
        # the two counted topics, once the probe subscribes to them: none of their messages goes unheard
        play = player_system.run(['rosbag', 'play', '--clock', '--wait-for-subscribers', bag,
                                  '--topics', '/tianracer/odom', '/scan'], timeout=60)
        assert play.returncode == 0, play.stderr
        played.touch()
        assert probe.wait(20) == 0
        counts = yaml.safe_load(probe.log().strip().splitlines()[-1])
    finally:
        player_system.close()
    assert counts == {'odom': recorded['/tianracer/odom'], 'scan': recorded['/scan']}
