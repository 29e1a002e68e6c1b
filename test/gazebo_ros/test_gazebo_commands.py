"""gazebo_ros's commands as Gazebo users and gazebo_ros_pkgs' own tests run them: `rosrun gazebo_ros
gzserver [options] WORLD` (the plant's node on the world, with Gazebo 11's options: -u, --iters, and
one warning for an option that does nothing here), `gzclient` (the browser viewer) and `gazebo` (both,
stopped together)."""
import socket
import urllib.request

import pytest

from plant_helpers import sdf_world
from ros_harness import free_port

pytestmark = pytest.mark.ros

CRATE = """<model name="crate"><pose>0 0 1 0 0 0</pose><link name="body">
  <inertial><mass>1</mass><inertia><ixx>0.0067</ixx><iyy>0.0067</iyy><izz>0.0067</izz></inertia></inertial>
  <collision name="shell"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model>"""


@pytest.fixture
def world(tmp_path):
    path = tmp_path / 'drop.world'
    path.write_text(sdf_world(CRATE))
    return str(path)


def port_open(port):
    with socket.socket() as s:
        return s.connect_ex(('127.0.0.1', port)) == 0


def crate_height(ros):
    return ros.probe('gazebo_ros/probes/model_poses.py', 'crate', timeout=60)['crate'][2]


def wait_for_gazebo(ros, process):
    ros.wait_until(lambda: process.popen.poll() is not None or
                   '/gazebo/get_model_state' in ros.services(), 60,
                   'the node\'s services')
    assert process.popen.poll() is None, process.log()


def test_gzserver_runs_the_world_paused_and_warns_once_of_an_option_it_does_not_know(ros, world):
    server = ros.start(['rosrun', 'gazebo_ros', 'gzserver', '-u', '--verbose', '-e', 'ode', '-s',
                        'libgazebo_ros_api_plugin.so', '--no_such_option', world, '__name:=gazebo'], 'gzserver')
    wait_for_gazebo(ros, server)
    assert crate_height(ros) == pytest.approx(1.0, abs=1e-9), 'paused by -u: the crate has not fallen'
    ros.service('/gazebo/unpause_physics')
    ros.wait_until(lambda: crate_height(ros) < 0.11, 30, 'the crate to land')
    log = server.log()
    assert log.count('--no_such_option') == 1 and 'unknown option' in log, log
    assert ros.get_param('/gazebo/lockstep') is False  # late frames skipped
    assert 'libgazebo_ros_api_plugin' not in log, 'gazebo_ros\'s own system plugin is no surprise'
    assert 'unregistered physics' not in log


def test_gzserver_iters_simulates_that_many_steps_and_stops(ros):
    run = ros.run(['rosrun', 'gazebo_ros', 'gzserver', '--iters', '250', '--lockstep', '__name:=gazebo'], timeout=60)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out
    assert '250 iterations simulated (~iterations), 0.250 s of simulated time' in out, out
    assert ros.get_param('/gazebo/lockstep') is True  # every camera frame rendered


def test_gzserver_refuses_log_playback_and_answers_help_and_version(ros):
    play = ros.run(['rosrun', 'gazebo_ros', 'gzserver', '-p', 'state.log'], timeout=30)
    assert play.returncode == 1 and '--play state.log' in play.stderr, play.stderr
    usage = ros.run(['rosrun', 'gazebo_ros', 'gzserver', '--help'], timeout=30)
    assert usage.returncode == 0 and '--iters' in usage.stdout and 'world_file' in usage.stdout
    version = ros.run(['rosrun', 'gazebo_ros', 'gzserver', '--version'], timeout=30)
    assert version.returncode == 0 and 'Gazebo 11' in version.stdout


def test_gazebo_runs_the_server_and_the_viewer_and_stops_both(ros, world):
    port = free_port()
    both = ros.start(['rosrun', 'gazebo_ros', 'gazebo', '-u', world, '-g', 'libsome_gui_plugin.so',
                      '__name:=gazebo', '_port:=%d' % port, '_open_browser:=false'], 'gazebo')
    wait_for_gazebo(ros, both)
    assert crate_height(ros) == pytest.approx(1.0, abs=1e-9)
    ros.wait_until(lambda: port_open(port), 60, 'the viewer\'s port')
    assert urllib.request.urlopen('http://127.0.0.1:%d/' % port, timeout=10).status == 200
    nodes = ros.run(['rosnode', 'list'], timeout=30).stdout.split()
    assert '/gazebo' in nodes and '/gazebo_gui' in nodes, nodes
    assert 'libsome_gui_plugin.so' in both.log(), 'a GUI plugin the viewer cannot load is said'
    both.interrupt()
    assert both.wait(30) is not None, both.log()
    assert not port_open(port), 'the viewer stopped with the server'


def test_gzclient_is_the_viewer(ros, world):
    server = ros.start(['rosrun', 'gazebo_ros', 'gzserver', world, '__name:=gazebo'], 'gzserver')
    wait_for_gazebo(ros, server)
    port = free_port()
    client = ros.start(['rosrun', 'gazebo_ros', 'gzclient', '--verbose', '__name:=gazebo_gui', '_port:=%d' % port,
                        '_open_browser:=false'], 'gzclient')
    ros.wait_until(lambda: port_open(port), 60, 'the viewer\'s port')
    page = urllib.request.urlopen('http://127.0.0.1:%d/' % port, timeout=10).read().decode()
    assert '<html' in page.lower(), page[:200]
    assert client.popen.poll() is None, client.log()
