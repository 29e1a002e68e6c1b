"""gazebo_ros's world launch files and the scripts beside gzserver, as Gazebo users start them:
`roslaunch gazebo_ros shapes_world.launch` (rubble, mud, willowgarage, elevator), each on this
package's own worlds/X.world standing in for Gazebo's, and `rosrun gazebo_ros debug` / `perf`
(gzserver under gdb / valgrind's callgrind). One roslaunch per launch file: each test reads the
world's models from /gazebo/model_states a few simulated seconds after the node is up; what the
files declare is read through roslaunch's own loader, starting nothing."""
import os
import subprocess

import pytest
import roslaunch.config
import roslaunch.xmlloader
import rospkg

ARGUMENTLESS = ['shapes_world.launch', 'rubble_world.launch', 'mud_world.launch', 'willowgarage_world.launch']


def launch_config(launch_file, *args):
    """What `roslaunch gazebo_ros LAUNCH_FILE ARGS...` would start, read by roslaunch's loader."""
    path = os.path.join(rospkg.RosPack().get_path('gazebo_ros'), 'launch', launch_file)
    config = roslaunch.config.ROSLaunchConfig()
    roslaunch.xmlloader.XmlLoader().load(path, config, argv=['roslaunch', *args], verbose=False)
    return config


def launch(ros, tmp_path, launch_file, *args):
    """roslaunch gazebo_ros LAUNCH_FILE gui:=false ARGS... once the node's services are up. No desktop
    for the viewer the argumentless files start (gui:=false is not theirs), and an empty
    GAZEBO_MODEL_PATH: what the worlds include comes from this package alone, whatever the machine
    has installed."""
    ros.env.pop('DISPLAY', None)
    ros.env.pop('WAYLAND_DISPLAY', None)
    models = tmp_path / 'no_models'
    models.mkdir()
    ros.env['GAZEBO_MODEL_PATH'] = str(models)
    plant = ros.start(['roslaunch', 'gazebo_ros', launch_file, 'gui:=false', *args], 'launch')
    ros.wait_until(lambda: plant.popen.poll() is not None or
                   '/gazebo/get_model_state' in ros.services(), 60,
                   'the node\'s services')
    assert plant.popen.poll() is None, plant.log()
    return plant


def states(ros, seconds, *links, not_before=0.0):
    return ros.probe('gazebo_ros/probes/world_launch_states.py', '--not-before=%g' % not_before, seconds, *links,
                     timeout=90)


def test_argumentless_world_launch_files_name_gazebos_world_and_start_the_client_whatever_gui_says():
    # Upstream's shapes/rubble/mud/willowgarage_world.launch declare no arguments: roslaunch leaves
    # gui:=false unused and the client (here the browser viewer) starts.
    for launch_file in ARGUMENTLESS:
        config = launch_config(launch_file, 'gui:=false', 'paused:=true')
        assert sorted(node.name for node in config.nodes) == ['gazebo', 'gazebo_gui'], launch_file
        world = 'worlds/%s.world' % launch_file[:-len('_world.launch')]
        server = next(node for node in config.nodes if node.name == 'gazebo')
        # gzserver's command line as upstream's empty_world.launch builds it: not paused (-u), the world last
        assert (server.package, server.type) == ('gazebo_ros', 'gzserver'), launch_file
        assert server.args.split() == ['-e', 'ode', world], (launch_file, server.args)


def test_elevator_world_launch_builds_upstreams_gzserver_command():
    # Upstream's default world, worlds/elevator_ros.world, is shipped by neither Gazebo nor gazebo_ros:
    # the node falls back on the empty world as gzserver does (test_worlds.py covers the fallback).
    (server, client) = launch_config('elevator_world.launch').nodes
    assert (server.name, server.package, server.type) == ('gazebo', 'gazebo_ros', 'gzserver')
    assert server.args.split() == ['--verbose', '-e', 'ode', 'worlds/elevator_ros.world']
    assert (client.name, client.package, client.type) == ('gazebo_gui', 'gazebo_ros', 'gzclient')
    (server,) = launch_config('elevator_world.launch', 'gui:=false', 'debug:=true', 'paused:=true',
                              'recording:=true', 'verbose:=false', 'physics:=bullet').nodes
    assert server.type == 'debug' and server.args.split() == ['-u', '-r', '-e', 'bullet', 'worlds/elevator_ros.world']


@pytest.mark.ros
def test_shapes_world_launch_rests_the_box_sphere_and_cylinder_on_the_ground(ros, tmp_path):
    plant = launch(ros, tmp_path, 'shapes_world.launch')
    out = states(ros, 1.0)
    assert set(out['models']) == {'ground_plane', 'box', 'sphere', 'cylinder'}, out
    for name, (x, y) in {'box': (0, 0), 'sphere': (0, 1.5), 'cylinder': (0, -1.5)}.items():
        px, py, pz, speed, spin = out['models'][name]
        # each rests at its half height (the cylinder on its side: its radius), where Gazebo's does
        assert (px, py, pz) == pytest.approx((x, y, 0.5), abs=0.01), (name, out)
        assert speed < 0.01 and spin < 0.02, (name, out)
    assert 'WoodPallet' not in plant.log(), 'our world paints with colours, not a textured material'


@pytest.mark.ros
def test_rubble_world_launch_drops_the_pile_between_its_walls_to_rest(ros, tmp_path):
    plant = launch(ros, tmp_path, 'rubble_world.launch')
    # Read at 6 s of the world's time or later. The pile (drawn once, seed 41) falls the same way on
    # every run and has shifted as late as 3.4 s (a board settling: speeds[90] 0.026 m/s at 3.34 s,
    # none over the bounds from 3.5 to 12 s); read 2 s after the probe started, a probe that started
    # early read it then (CI, stop 59: 0.022).
    out = states(ros, 2.0, not_before=6.0)
    walls = {'ground_plane', 'right_wall', 'left_wall'}  # static models, listed as Gazebo lists them
    assert set(out['models']) == walls | {'rubble_%d' % i for i in range(100)}, sorted(out['models'])
    rubble = {name: state for name, state in out['models'].items() if name not in walls}
    for name, (x, y, z, speed, spin) in rubble.items():
        # between the walls (inner faces at y -1 and 1), on the ground or the pile, none thrown out
        assert abs(x) < 2.5 and abs(y) < 1.0 and 0.0 < z < 1.2, (name, out['models'][name])
    speeds = sorted(v[3] for v in rubble.values())
    assert speeds[90] < 0.02 and speeds[-1] < 0.2, speeds  # fallen into place: at rest
    assert 'deep inside' not in plant.log(), 'no piece starts inside another'


@pytest.mark.ros
def test_mud_world_launch_swings_its_pendulums_and_warns_of_the_mud_plugin(ros, tmp_path):
    plant = launch(ros, tmp_path, 'mud_world.launch')
    pendulums = ['pendulum_thick_mud', 'pendulum_thin_mud', 'pendulum_no_mud']
    out = states(ros, 2.0, *['%s::lower_link' % p for p in pendulums])
    # the pits are static models with a plugin: models, as in Gazebo
    assert set(out['models']) == set(pendulums) | {'ground_plane', 'mud_pit_thin', 'mud_pit_thick'}, out['models']
    for name in pendulums:
        base = out['models'][name]
        assert base[2] == pytest.approx(0.0, abs=0.02), (name, base)  # the base stands on the ground
        # released near horizontal, undamped: the elbow (the lower link's origin) swings metres in 2 s
        swing = out['links'][name + '::lower_link']
        assert swing['travel'] > 1.0, (name, swing)
    travels = [out['links'][name + '::lower_link']['travel'] for name in pendulums]
    assert max(travels) < 1.01 * min(travels), travels  # the mud is not simulated: all three swing alike
    log = plant.log()
    assert log.count('libMudPlugin.so') == 2, log  # one warning per pit


@pytest.mark.ros
def test_willowgarage_world_launch_without_the_model_is_the_ground_and_the_sun_and_says_so(ros, tmp_path):
    plant = launch(ros, tmp_path, 'willowgarage_world.launch')
    out = states(ros, 0.5)
    assert list(out['models']) == ['ground_plane'], out
    log = plant.log()
    assert "<include> of 'model://willowgarage'" in log and 'skipped' in log, log


@pytest.mark.ros
def test_elevator_world_launch_runs_gazebos_elevator_world_with_its_cars_at_floor_0(ros, tmp_path):
    plant = launch(ros, tmp_path, 'elevator_world.launch', 'world_name:=worlds/elevator.world')
    out = states(ros, 1.0)
    # each shaft is a static model named as its car (Gazebo's world names them so); the floors too
    assert set(out['models']) == {'ground_plane', 'elevator1', 'elevator2', 'floor0', 'floor1', 'floor2', 'floor3'}, out
    for name, y in (('elevator1', -1.5), ('elevator2', 1.5)):
        # Gazebo's libElevatorPlugin holds each car at floor 0 until it is called to another
        assert out['models'][name][:3] == pytest.approx([0, y, 0.1], abs=0.01), out
    log = plant.log()
    said = [line for line in log.splitlines() if 'libElevatorPlugin.so' in line and 'loaded from' not in line]
    assert not said and 'Unable to find' not in log and 'floor_height' not in log, log


@pytest.mark.ros
def test_debug_runs_gzserver_under_gdb(ros):
    # gdb runs the node at once, as gazebo_ros's gdbrun, and quits at its prompt on the end of stdin
    run = ros.run(['rosrun', 'gazebo_ros', 'debug', '--iters', '20', '__name:=gazebo'], timeout=90, input='')
    out = run.stdout + run.stderr
    assert 'gdb is not installed' not in out, 'install gdb (tools/setup.sh does)'
    assert run.returncode == 0, out
    assert '20 iterations simulated (~iterations)' in out and 'exited normally' in out, out


@pytest.mark.parametrize('script, tool', [('debug', 'gdb'), ('perf', 'valgrind')])
def test_debug_and_perf_name_the_package_to_install_when_their_tool_is_missing(tmp_path, script, tool):
    scripts = os.path.join(rospkg.RosPack().get_path('gazebo_ros'), 'scripts')
    env = dict(os.environ, PATH=str(tmp_path))  # neither gdb nor valgrind on it
    run = subprocess.run(['/usr/bin/python3', os.path.join(scripts, script), '--iters', '1'], env=env,
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 1 and 'sudo apt-get install %s' % tool in run.stderr, run.stderr
    usage = subprocess.run(['/usr/bin/python3', os.path.join(scripts, script), '--help'], env=env,
                           capture_output=True, text=True, timeout=60)
    assert usage.returncode == 0 and '--iters' in usage.stdout, usage.stderr
