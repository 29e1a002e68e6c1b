"""Spawning and deleting models all day does not grow the simulator: an SDF and a URDF model, each with
a camera, a laser and a p3d plugin whose topics have subscribers (so every sensor runs), spawned and
deleted through gazebo_ros's services SPAWN_DELETE_CYCLES times each (150 in the suite; the issue's
bound, 5 MB, is for 1000, which `SPAWN_DELETE_CYCLES=1000` runs), and the node's resident memory from
the end of the first tenth to the end."""
import os

import pytest

from ros_harness import RosSystem, plant_pid

pytestmark = [pytest.mark.ros, pytest.mark.slow]

CYCLES = int(os.environ.get('SPAWN_DELETE_CYCLES', '150'))
MAX_GROWTH_KB = 5 * 1024  # the bound, for 1000 cycles of each


def test_a_thousand_spawn_delete_cycles_keep_the_node_the_same_size(tmp_path):
    ros = RosSystem(str(tmp_path))
    try:
        # Three times real time: the sensors' first messages after a spawn come three times sooner
        # than at real time, and the node spends 24 s of CPU on the 300 cycles, against 55 s as fast
        # as it can (real_time_factor:=0), in the same wall time (35 s alone)
        plant = ros.start(['roslaunch', 'gazebo_ros', 'empty_world.launch', 'gui:=false', 'real_time_factor:=3'],
                          'plant')
        pid = plant_pid(plant.pid)
        out = ros.probe('gazebo_ros/probes/spawn_delete_cycles.py', CYCLES, pid, timeout=60 + 2 * CYCLES)
    finally:
        ros.close()
    assert not out['failures'], out['failures']
    # The first cycles' growth is the allocator and roscpp settling (+0.6 to 1.3 MB over 150 to 200
    # cycles); over 1000 cycles each the RSS grew +100 KB (SDF) and +28 KB (URDF) after the first
    # tenth. The bound is for 1000 cycles; the suite runs fewer and holds them to it whole.
    for kind, samples in out['kb'].items():
        assert samples[-1] - samples[0] < MAX_GROWTH_KB, (kind, samples)
    # the sensors ran in the cycles: every topic heard in all but a few (rospy's reconnection race)
    assert len(out['unheard']) < 0.05 * 2 * CYCLES, out['unheard']
