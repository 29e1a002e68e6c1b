"""What the node publishes is built on the simulation thread and published by threads of their own
(~publishing_threads, src/node/outbox.h): the number of them must not change what is simulated. The
diff_bot driven on a circle by one command given before the simulation starts, with the simulation
thread publishing (0) and with two publishing threads: every odometry message and every scan with the
same stamp in both runs is the same to the last bit."""
import pytest

from plant_helpers import DIFF_BOT
from ros_harness import spawn_urdf

pytestmark = pytest.mark.ros

SIMULATED = 2.0  # s


def driven(ros, threads):
    """The diff_bot's /odom and /scan by stamp over SIMULATED s, the node publishing on `threads`."""
    plant = ros.start(['rosrun', 'gazebo_ros', 'gzserver', '-u', 'worlds/arena.world',
                       '_publishing_threads:=%d' % threads], 'plant_%d' % threads)
    try:
        spawn_urdf(ros, plant, '/robot_description', 'diff_bot', xyz=(0.0, 0.0, 0.05))
        seen = ros.probe('node/probes/a_driven_robot_as_published.py', SIMULATED, timeout=120)
        assert 'publishing on %d thread' % threads in plant.log() if threads else \
            'publishing on the simulation thread' in plant.log(), plant.log()
        return seen
    finally:
        plant.interrupt()
        plant.wait(10)


def test_the_simulation_is_the_same_whichever_thread_publishes(ros):
    ros.set_param('/use_sim_time', True)
    ros.set_param('/robot_description', textfile=DIFF_BOT)
    inline, threaded = driven(ros, 0), driven(ros, 2)
    for topic, least in (('odom', 40), ('scans', 5)):
        common = sorted(set(inline[topic]) & set(threaded[topic]))
        assert len(common) >= least, (topic, len(inline[topic]), len(threaded[topic]))
        different = [stamp for stamp in common if inline[topic][stamp] != threaded[topic][stamp]]
        assert not different, '%s differs at %s: %s vs %s' % (topic, different[0], inline[topic][different[0]],
                                                               threaded[topic][different[0]])
    moved = inline['odom'][max(inline['odom'])]
    assert abs(moved[0]) + abs(moved[1]) > 0.1, 'the robot drove: %s' % moved
