"""A Gazebo user's own robot package on the plant, as README's "Your robot on the plant" walks it: the
plant's install space (`make install`), sourced as /opt/ros is; the user's own workspace built on it with
catkin_make (once for the module: the robot's package and a package of Gazebo plugins of the user's
own) and with catkin_tools' `catkin build`; the robot's own gazebo launch file run unchanged
(test/fixtures/rover_description: gazebo_ros's empty_world.launch, xacro, spawn_model, gazebo_plugins'
diff drive); the user's plugins loaded by the plant (test/fixtures/gazebo_plugin_pkg). Each step runs in a clean environment that sources only what a user would, so nothing
of the source tree or its devel space can stand in for the install. And a clone of this repository
in a workspace's src/ is refused with what to do."""
import json
import math
import os
import shutil
import subprocess

import pytest
import yaml

from ros_harness import RosSystem
from suite_paths import FIXTURES, REPOSITORY, TEST_DIR

pytestmark = pytest.mark.ros

ROVER = os.path.join(FIXTURES, 'rover_description')
# A user's shell: nothing of ROS sourced, Debian's interpreter first (catkin and rostest run
# `/usr/bin/env python3`).
CLEAN_ENV = {'HOME': os.environ.get('HOME', '/root'), 'PATH': '/usr/bin:/bin', 'LANG': 'C.UTF-8'}


def run(command, cwd, timeout=300):
    """A shell command line in the clean environment: returns (exit status, output)."""
    done = subprocess.run(['bash', '-c', command], cwd=cwd, env=CLEAN_ENV, capture_output=True, text=True,
                          timeout=timeout)
    return done.returncode, done.stdout + done.stderr


def sourced(setup_bash):
    """The environment after `source SETUP_BASH` in a clean shell."""
    status, output = run('source %s && env -0' % setup_bash, cwd='/')
    assert status == 0, output
    return dict(entry.split('=', 1) for entry in output.split('\0') if '=' in entry)


@pytest.fixture(scope='module')
def install_space():
    """`make install`, as the README says, once for the module: the install space's folder."""
    # The suite runs on a built workspace (make test builds first): `-o build` takes it as made, so this
    # is the README's `make install` without building again.
    status, output = run('make -o build install', cwd=REPOSITORY, timeout=900)
    assert status == 0, output
    prefix = output.strip().splitlines()[-1].split('source ', 1)[1].rsplit('/setup.bash', 1)[0]
    assert os.path.isfile(os.path.join(prefix, 'setup.bash')), output
    return prefix


def user_workspace(root):
    workspace = root / 'rover_ws'
    shutil.copytree(ROVER, workspace / 'src' / 'rover_description')
    return workspace


@pytest.fixture(scope='module')
def catkin_make_workspace(install_space, tmp_path_factory):
    """One user workspace with the robot's package and a package of Gazebo plugins of its own
    (test/fixtures/gazebo_plugin_pkg), built once with catkin_make on the install space, as a user's
    workspace holds both: (workspace, its devel space's environment, catkin_make's output)."""
    workspace = user_workspace(tmp_path_factory.mktemp('user'))
    shutil.copytree(os.path.join(FIXTURES, 'gazebo_plugin_pkg'), workspace / 'src' / 'gazebo_plugin_pkg')
    status, output = run('source %s/setup.bash && catkin_make' % install_space, cwd=workspace)
    assert status == 0, output
    return workspace, sourced(workspace / 'devel' / 'setup.bash'), output


def test_a_robot_package_built_with_catkin_make_on_the_install_space_runs_its_gazebo_launch_file(
        install_space, catkin_make_workspace, tmp_path):
    workspace, env, _ = catkin_make_workspace
    # The plant's packages come from the install space, the rover from the user's workspace.
    for package, where in (('gazebo_ros', install_space), ('tianracer_description', install_space),
                           ('xacro', install_space), ('rover_description', str(workspace / 'src'))):
        found = subprocess.run(['rospack', 'find', package], env=env, capture_output=True, text=True)
        assert found.stdout.startswith(where), (package, found.stdout, found.stderr)

    ros = RosSystem(str(tmp_path), base_env=env)
    try:
        launch = ros.start(['roslaunch', 'rover_description', 'gazebo.launch', 'gui:=false'], 'roslaunch')
        ros.wait_until(lambda: launch.popen.poll() is not None or 'rover' in ros.service(
            '/gazebo/get_world_properties', wait=True, timeout=60)['model_names'], 60, 'the rover spawned')
        assert launch.popen.poll() is None, launch.log()
        start = ros.probe('gazebo_ros/probes/model_poses.py', 'rover')['rover']
        drive = ros.start(['rostopic', 'pub', '-r', '10', '/cmd_vel', 'geometry_msgs/Twist',
                           '{linear: {x: 0.3}}'], 'cmd_vel')
        ros.wait_until(lambda: ros.probe('gazebo_ros/probes/model_poses.py', 'rover')['rover'][0] > start[0] + 0.2,
                       30, 'the rover to drive 0.2 m forward on cmd_vel (gazebo_plugins\' diff drive)')
        drive.stop()
        assert 'ERROR' not in launch.log(), launch.log()
    finally:
        ros.close()


def test_a_robot_package_builds_with_catkin_tools_on_the_install_space(install_space, tmp_path):
    workspace = user_workspace(tmp_path)
    status, output = run('catkin init && catkin config --extend %s && catkin build --no-status --no-notify'
                         % install_space, cwd=workspace)
    assert status == 0, output
    env = sourced(workspace / 'devel' / 'setup.bash')
    # roslaunch resolves the launch file whole: gazebo_ros's empty_world.launch, the plant's node, and
    # the xacro command through the install space's xacro.
    params = subprocess.run(['roslaunch', '--dump-params', 'rover_description', 'gazebo.launch'], env=env,
                            capture_output=True, text=True, timeout=60)
    assert params.returncode == 0, params.stderr
    assert 'libgazebo_ros_diff_drive.so' in params.stdout and '/gazebo/enable_ros_network: true' in params.stdout
    nodes = subprocess.run(['roslaunch', '--nodes', 'rover_description', 'gazebo.launch', 'gui:=false'], env=env,
                           capture_output=True, text=True, timeout=60)
    assert nodes.stdout.split() == ['/gazebo', '/spawn_rover'], nodes.stdout + nodes.stderr


@pytest.mark.slow
def test_a_package_with_its_own_gazebo_plugin_builds_on_the_install_space_with_gazebo_dev_and_pkg_config(
        install_space, catkin_make_workspace, tmp_path):
    """test/fixtures/gazebo_plugin_pkg: catkin's gazebo_dev and find_package(gazebo) (Gazebo 11's C++
    API, GAZEBO_LIBRARIES), a model plugin library and a node that makes the plugin from its file
    and loads it with its <plugin> element read by sdformat; and a program built by `pkg-config
    gazebo` alone."""
    workspace, env, output = catkin_make_workspace
    assert '-- Gazebo version: 11.15' in output, output
    check = subprocess.run([str(workspace / 'devel' / 'lib' / 'gazebo_plugin_pkg' / 'plugin_check')],
                           env=dict(env, GAZEBO_PLUGIN_PATH=str(workspace / 'devel' / 'lib')),
                           capture_output=True, text=True, timeout=30)
    assert check.returncode == 0, check.stdout + check.stderr
    assert check.stdout.split('\n')[:2] == ['hello_model: hi', 'gazebo 11 plugin hello type model step 0.001'], \
        check.stdout
    # The plant loads the package's plugin library (found on LD_LIBRARY_PATH, where the workspace's
    # devel/lib is) for a <plugin> of that file name, and the plugin moves its models.
    moved = subprocess.run(['/usr/bin/python3', os.path.join(TEST_DIR, 'gazebo_ros', 'probes',
                                                              'user_model_plugin_moves_its_model.py'), str(tmp_path)],
                           env=env, capture_output=True, text=True, timeout=120)
    assert moved.returncode == 0, moved.stdout + moved.stderr
    motion = json.loads(moved.stdout.strip().splitlines()[-1])
    errors = [text for level, text in motion['messages'] if level == 'ERROR']
    # A library that is no Gazebo plugin: one error naming the plugin and the file; the model runs.
    assert len(errors) == 1 and "plugin 'push' (/lib/x86_64-linux-gnu/libm.so.6)" in errors[0] \
        and 'has no RegisterPlugin' in errors[0], errors
    assert motion['end']['broken'][2] < motion['start']['broken'][2] - 0.3, motion  # it fell to the ground
    pushed_x = motion['end']['pushed'][0] - motion['start']['pushed'][0]
    assert 0.27 < pushed_x < 0.33, motion  # SetLinearVel(0.3, 0, 0) each update for 1 s
    assert abs(motion['spin'][1] - 2.0) < 0.05, motion  # Joint::SetVelocity(0, 2.0)
    lifted_z = motion['end']['lifted'][2] - motion['start']['lifted'][2]
    assert 4.0 < lifted_z < 5.5, motion  # Link::AddForce of twice its weight: up at g, 4.9 m in 1 s
    steps, last, world_time, name, mass, _, effort_limit, _, top_height = motion['reports']['pushed']
    assert int(steps) == 1000 and abs(float(last) - 0.999) < 1e-9 and name == 'pushed_cart', motion['reports']
    assert float(mass) == 2.0, motion['reports']  # Link::GetInertial: the base link's own <inertial>
    assert float(effort_limit) == -1.0, motion['reports']  # GetEffortLimit: the continuous joint gives none
    assert float(top_height) == 0.1, motion['reports']  # Link::RelativePose: the joint's origin in the model
    # Joint::SetForce twice a step, 0.002 N m each: GetForce says the step's sum, and the top (0.001
    # kg m^2 on a base of 0.04 about z) spins up at some 4 rad/s^2 relative to the base
    assert float(motion['reports']['lifted'][7]) == 0.004, motion['reports']
    assert 3.0 < motion['twisted_spin'][1] < 5.0, motion['twisted_spin']
    # The last of 50 carts spawned under one name after deletes moved by its own plugin in its 10 ms.
    assert 0.0025 < motion['respawned_x'] < 0.0035, motion['respawned_x']
    # SetParam("fmax", 0.5) and ("vel", 1.5): the joint's motor turns it at 1.5 rad/s (GetParam says so)
    assert abs(motion['motor'][1] - 1.5) < 0.01 and float(motion['reports']['motored'][5]) == 1.5, motion
    # The model's joint controller (JointController, common::PID) holds the joint at its 1 rad target.
    assert abs(motion['held'][0] - 1.0) < 0.02 and abs(motion['held'][1]) < 0.05, motion['held']
    # 0.5 N along x at 0.15 m to the left of the floating cart's centre of mass: it moves 0.11 m
    # (0.5 / 2.2 kg for 1 s) and turns right at 0.075 N m / 0.04 kg m^2 (0.94 rad in 1 s).
    start, end = motion['start']['twisted'], motion['end']['twisted']
    yaw = 2 * math.atan2(end[5], end[6])
    assert 0.09 < end[0] - start[0] < 0.13 and -1.05 < yaw < -0.8 and abs(end[2] - start[2]) < 0.02, (start, end)
    # The headers and libraries come from the install space, not from the source tree.
    flags = subprocess.run(['pkg-config', '--cflags', '--libs', 'gazebo'], env=env, capture_output=True, text=True)
    assert flags.returncode == 0 and install_space + '/include/gazebo-11' in flags.stdout, flags.stdout + flags.stderr
    (tmp_path / 'clock.cc').write_text(
        '#include <gazebo/common/Time.hh>\n#include <iostream>\n'
        'int main() { std::cout << (gazebo::common::Time(1.5) - gazebo::common::Time(0, 250000000)).Double()'
        ' << std::endl; }\n')
    status, output = run('source %s/setup.bash && g++ clock.cc -o clock $(pkg-config --cflags --libs gazebo) && ./clock'
                         % install_space, cwd=tmp_path)
    assert status == 0 and output.strip() == '1.25', output


def test_this_repository_cloned_into_a_workspace_is_refused_with_what_to_do(tmp_path):
    workspace = tmp_path / 'clone_ws'
    (workspace / 'src').mkdir(parents=True)
    os.symlink(REPOSITORY, workspace / 'src' / 'tianracer_description')
    status, output = run('catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3', cwd=workspace)
    assert status != 0
    message = ' '.join(output.split())  # CMake folds a message's lines
    assert "catkin does not look for packages inside a package" in message, output
    assert 'tianracer_description/compat/* src/' in message, output  # link the packages beside it
    assert 'make install' in message, output  # or extend the install space


# The world of the user's world plugin (attach_world): a carrier box it drives along x, a cargo box
# behind it that it holds to the carrier from 0.5 to 1.5 s; beside it, the same plugin told to
# throw in Load and a plugin whose file is nowhere, which Gazebo reports and runs the world without.
ATTACH_WORLD = """<?xml version="1.0"?>
<sdf version="1.7">
  <world name="default">
    <include><uri>model://ground_plane</uri></include>
    %s
    %s
    <plugin name="attach" filename="libattach_world.so">
      <carrier>carrier</carrier><cargo>cargo</cargo><speed>0.3</speed><attach_at>0.5</attach_at><detach_at>1.5</detach_at>
    </plugin>
    <plugin name="thrower" filename="libattach_world.so"><throw_in_load>true</throw_in_load></plugin>
    <plugin name="missing" filename="libno_such_plugin.so"/>
  </world>
</sdf>
"""
BOX = """<model name="{name}"><pose>{x} 0 {half} 0 0 0</pose><link name="body">
      <inertial><mass>{mass}</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>{size} {size} {size}</size></box></geometry></collision>
    </link></model>"""


@pytest.mark.slow
def test_a_world_plugin_and_a_system_plugin_of_the_users_run_under_gzserver(catkin_make_workspace, tmp_path):
    """gazebo_ros's empty_world.launch with extra_gazebo_args:="-s libhello_system.so" (gzserver -s) on a
    world naming the user's world plugin, as a user's launch file starts them: the world plugin
    (physics::World's ModelByName, Physics()->CreateJoint, Joint::Load / Init / Detach) carries the
    cargo for the second it holds it, read through gazebo_ros's get_model_state; the system plugin
    has the server's command line, the world (physics::get_world) and its updates and says so on ROS."""
    workspace, env, _ = catkin_make_workspace
    world = tmp_path / 'attach.world'
    world.write_text(ATTACH_WORLD % (BOX.format(name='carrier', x=0.0, half=0.1, mass=2.0, size=0.2),
                                     BOX.format(name='cargo', x=-0.4, half=0.05, mass=0.5, size=0.1)))
    ros = RosSystem(str(tmp_path), base_env=env)
    try:
        server = ros.start(['roslaunch', 'gazebo_ros', 'empty_world.launch', 'world_name:=%s' % world, 'paused:=true',
                            'verbose:=true', 'gui:=false', 'extra_gazebo_args:=-s libhello_system.so'], 'gzserver')

        def x_of(model):
            return ros.service('/gazebo/get_model_state', '{model_name: %s}' % model)['pose']['position']['x']
        ros.service('/gazebo/get_world_properties', wait=True, timeout=60)
        start = {model: x_of(model) for model in ('carrier', 'cargo')}
        ros.service('/gazebo/unpause_physics')
        ros.wait_until(lambda: ros.service('/gazebo/get_world_properties')['sim_time'] >= 2.0, 60, '2 s simulated')
        ros.service('/gazebo/pause_physics')
        end = {model: x_of(model) for model in ('carrier', 'cargo')}
        hello = yaml.safe_load(ros.run(['rostopic', 'echo', '-n', '1', '/hello_system'],
                                       timeout=30).stdout.split('\n---')[0])['data']
        log = server.log()
    finally:
        ros.close()
    assert 'attach_world in world [default] of 2 models, step 0.001 s' in log, log
    assert end['carrier'] - start['carrier'] > 0.55, (start, end)  # driven at 0.3 m/s for 2 s and more
    # Held for 1 s at 0.3 m/s, then let go: it slides 5 mm more on the ground (mu 1)
    assert 0.27 < end['cargo'] - start['cargo'] < 0.36, (start, end, log)
    errors = [line for line in log.splitlines() if 'ERROR' in line or '[Err]' in line]
    assert any("world plugin 'thrower' (libattach_world.so): its Load threw: attach_world was told to throw" in line
               for line in errors), log
    assert "world plugin 'missing' (libno_such_plugin.so)" in log and 'no such file on GAZEBO_PLUGIN_PATH' in log, log
    assert 'world default; updates' in hello and '; models 2;' in hello and 'arguments gzserver -u --verbose -e ode -s libhello_system.so %s' % world in hello, hello


# The world of the user's factory plugin and animated models: an arm whose joint the user's model
# plugin swings through key frames, a static box it slides along x (Gazebo's animate_joints and
# animate_pose examples; animate_pose's box is static too), and a world plugin that adds models in its Load as Gazebo's factory example does (a model
# file by URI, SDF text twice under one name, sdformat's SDF renamed; and a model it cannot read).
FACTORY_WORLD = """<?xml version="1.0"?>
<sdf version="1.7">
  <world name="default">
    <include><uri>model://ground_plane</uri></include>
    <model name="arm">
      <joint name="fixed_to_world" type="fixed"><parent>world</parent><child>base</child></joint>
      <link name="base"><pose>0 0 0.1 0 0 0</pose>
        <inertial><mass>5</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial>
        <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
      </link>
      <link name="boom"><pose>0.3 0 0.25 0 0 0</pose>
        <inertial><mass>0.5</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
        <collision name="c"><geometry><box><size>0.5 0.05 0.05</size></box></geometry></collision>
      </link>
      <joint name="swing" type="revolute"><parent>base</parent><child>boom</child>
        <pose>-0.3 0 0 0 0 0</pose><axis><xyz>0 0 1</xyz></axis></joint>
      <plugin name="animate" filename="libanimate_model.so"><joint>swing</joint><swing>1.2</swing></plugin>
    </model>
    <model name="slider"><static>true</static><pose>0 -2 0.1 0 0 0</pose>
      <link name="body">
        <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
        <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
      </link>
      <plugin name="animate" filename="libanimate_model.so"><move>1.0</move></plugin>
    </model>
    <plugin name="factory" filename="libfactory_world.so">
      <model_uri>model://crate</model_uri><sphere_name>ball</sphere_name><box_name>renamed_box</box_name>
    </plugin>
  </world>
</sdf>
"""
CRATE_MODEL = """<?xml version="1.0"?>
<sdf version="1.6"><model name="crate"><pose>-2 3 0.25 0 0 0</pose><link name="link">
  <inertial><mass>2</mass></inertial>
  <collision name="c"><geometry><box><size>0.5 0.5 0.5</size></box></geometry></collision>
</link></model></sdf>
"""


# A box resting on the ground before a wall whose face is 1.4 m ahead of its lidar, with the user's
# sensor plugins: nearest_ray (a RayPlugin) on its ray sensor and on its camera, which a RayPlugin
# cannot take; touch_report on its contact sensor; frame_report (a CameraPlugin) on a camera facing
# the wall.
SENSOR_WORLD = """<?xml version="1.0"?>
<sdf version="1.7">
  <world name="default">
    <include><uri>model://ground_plane</uri></include>
    <model name="wall"><static>true</static><pose>1.6 0 0.5 0 0 0</pose><link name="body">
      <collision name="c"><geometry><box><size>0.2 3 1</size></box></geometry></collision></link></model>
    <model name="probe"><pose>0 0 0.1 0 0 0</pose><link name="base">
      <inertial><mass>2</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
      <sensor type="ray" name="lidar"><pose>0.1 0 0.05 0 0 0</pose><update_rate>10</update_rate>
        <ray><scan><horizontal><samples>5</samples><min_angle>-0.3</min_angle><max_angle>0.3</max_angle></horizontal>
          </scan><range><min>0.1</min><max>5</max></range></ray>
        <plugin name="nearest" filename="libnearest_ray.so"><report>/nearest_ray</report></plugin>
      </sensor>
      <sensor type="contact" name="bumper"><update_rate>20</update_rate>
        <contact><collision>c</collision></contact>
        <plugin name="touch" filename="libtouch_report.so"><report>/touch_report</report></plugin>
      </sensor>
      <sensor type="camera" name="look"><pose>0.1 0 0.05 0 0 0</pose><update_rate>5</update_rate>
        <camera><horizontal_fov>0.8</horizontal_fov><image><width>8</width><height>6</height><format>L8</format></image>
        </camera>
        <plugin name="frames" filename="libframe_report.so"><report>/frame_report</report></plugin>
      </sensor>
      <sensor type="camera" name="eye"><update_rate>5</update_rate>
        <camera><image><width>8</width><height>6</height></image></camera>
        <plugin name="wrong" filename="libnearest_ray.so"/>
      </sensor>
    </link></model>
  </world>
</sdf>
"""


@pytest.mark.slow
def test_sensor_plugins_of_the_users_read_their_ray_contact_and_camera_sensors_under_gzserver(
        catkin_make_workspace, tmp_path):
    """The user's RayPlugin on a ray sensor of a world file under gzserver: OnNewLaserScans after each
    scan at the sensor's 10 Hz, the laser shape's nearest ray the wall's face, the sensor's
    LaserScanStamped messages on its Gazebo topic reaching the plugin's own subscriber (which keeps
    the sensor measuring), SensorManager finding it by name; on a camera it is refused, naming the
    sensor and the plugin, and the world runs. The user's contact plugin on the same box: each 20 Hz
    measurement, the box's collision touching the ground's with the box's weight, msgs::Contacts on
    the sensor's Gazebo topic. The user's CameraPlugin on a camera facing the wall: each 5 Hz frame in
    its L8 format, 8 x 6 x 1, its field of view, msgs::ImageStamped on the sensor's topic."""
    workspace, env, _ = catkin_make_workspace
    world = tmp_path / 'sensor.world'
    world.write_text(SENSOR_WORLD)
    ros = RosSystem(str(tmp_path), base_env=env)
    try:
        ros.set_param('/use_sim_time', True)
        server = ros.start(['rosrun', 'gazebo_ros', 'gzserver', '-u', '--verbose', str(world)], 'gzserver')
        ros.service('/gazebo/get_world_properties', wait=True, timeout=60)
        ros.service('/gazebo/unpause_physics')
        ros.wait_until(lambda: ros.service('/gazebo/get_world_properties')['sim_time'] >= 2.0, 60, '2 s simulated')
        ros.service('/gazebo/pause_physics')
        sim_time = ros.service('/gazebo/get_world_properties')['sim_time']
        report, touch, look = [yaml.safe_load(ros.run(['rostopic', 'echo', '-n', '1', topic],
                                                timeout=30).stdout.split('\n---')[0])['data'].split()
                         for topic in ('/nearest_ray', '/touch_report', '/frame_report')]
        log = server.log()
    finally:
        ros.close()
    seen = dict(zip(report[0::2], report[1::2]))
    assert seen['topic'] == '~/probe/base/lidar/scan', 'RaySensor::Topic(): ~/PARENT/SENSOR/scan, :: as /'
    assert seen['found'] == '1', 'SensorManager::GetSensor("lidar") is its sensor'
    assert seen['ranges'] == '5'
    assert float(seen['nearest']) == pytest.approx(1.6 - 0.1 - 0.1, abs=5e-3), 'the wall face, 1.4 m ahead'
    scans = int(seen['scans'])
    assert abs(scans - 10 * sim_time) <= 2, (scans, sim_time)
    # its own subscriber has had each scan but perhaps the last, still on its way
    assert scans - 2 <= int(seen['messages']) <= scans, seen
    assert sim_time - 0.1 - 1e-6 <= float(seen['stamp']) <= sim_time, (seen, sim_time)  # the last scan's time
    assert "sensor 'lidar' plugin 'nearest' (libnearest_ray.so): loaded from" in log, log
    touched = dict(zip(touch[0::2], touch[1::2]))
    assert touched['collision'] == 'probe::base::c'
    assert touched['touching'] == 'ground_plane::link::collision'
    assert int(touched['points']) >= 1
    assert abs(float(touched['force'])) == pytest.approx(2 * 9.8, abs=0.3), 'the 2 kg box rests on the ground'
    updates = int(touched['updates'])
    assert abs(updates - 20 * sim_time) <= 2, (updates, sim_time)
    assert updates - 2 <= int(touched['messages']) <= updates, touched
    looked = dict(zip(look[0::2], look[1::2]))
    assert [looked['size'], looked['format'], looked['topic']] == ['8x6x1', 'L8', '~/probe/base/look/image']
    assert float(looked['hfov']) == pytest.approx(0.8)
    frames = int(looked['frames'])
    assert abs(frames - 5 * sim_time) <= 2, (frames, sim_time)
    assert frames - 2 <= int(looked['messages']) <= frames, looked
    assert 0 < float(looked['mean']) < 255, 'a rendered frame: the wall and the sky'
    errors = [line for line in log.splitlines() if 'ERROR' in line or '[Err]' in line]
    assert any("sensor 'eye' plugin 'wrong' (libnearest_ray.so)" in line and 'the plugin is not loaded' in line
               for line in errors), log


def factory_world(root):
    """FACTORY_WORLD written in `root`, and a model folder with the crate its plugin inserts by URI:
    (the world file, the folder for GAZEBO_MODEL_PATH)."""
    models = root / 'models'
    (models / 'crate').mkdir(parents=True)
    (models / 'crate' / 'model.config').write_text(
        '<?xml version="1.0"?><model><name>crate</name><sdf version="1.6">model.sdf</sdf></model>')
    (models / 'crate' / 'model.sdf').write_text(CRATE_MODEL)
    world = root / 'factory.world'
    world.write_text(FACTORY_WORLD)
    return world, models


@pytest.mark.slow
def test_a_world_plugin_inserts_models_and_a_model_plugin_animates_joints_and_poses_under_gzserver(
        catkin_make_workspace, tmp_path):
    """The user's world plugin (World::InsertModelFile / InsertModelString / InsertModelSDF) adds its
    models after the world's first update, paused as it is, named as Gazebo names them, and the world
    goes on past the one it cannot read; the user's model plugin (Model::SetJointAnimation,
    SetAnimation over common::NumericAnimation and PoseAnimation) moves the arm's joint and the slider
    where the key frames say at each simulated time, and is told when each animation completes."""
    workspace, env, _ = catkin_make_workspace
    world, models = factory_world(tmp_path)
    ros = RosSystem(str(tmp_path), base_env=dict(env, GAZEBO_MODEL_PATH=str(models)))
    try:
        ros.set_param('/use_sim_time', True)
        server = ros.start(['rosrun', 'gazebo_ros', 'gzserver', '-u', '--verbose', str(world)], 'gzserver')
        ros.service('/gazebo/get_world_properties', wait=True, timeout=60)
        inserted = {'crate', 'ball', 'ball_0', 'renamed_box'}
        ros.wait_until(lambda: inserted <= set(ros.service('/gazebo/get_world_properties')['model_names']), 30,
                       'the models the factory plugin inserted, while paused')
        paused_time = ros.service('/gazebo/get_world_properties')['sim_time']
        names = ros.service('/gazebo/get_world_properties')['model_names']
        placed = {name: ros.service('/gazebo/get_model_state', '{model_name: %s}' % name)['pose']['position']
                  for name in ('crate', 'ball', 'ball_0', 'renamed_box')}
        slider_start = ros.service('/gazebo/get_model_state', '{model_name: slider}')['pose']['position']['x']

        def run_to(seconds):
            ros.service('/gazebo/unpause_physics')
            ros.wait_until(lambda: ros.service('/gazebo/get_world_properties')['sim_time'] >= seconds, 60,
                           '%s s simulated' % seconds)
            ros.service('/gazebo/pause_physics')
            now = ros.service('/gazebo/get_world_properties')['sim_time']
            swing = ros.service('/gazebo/get_joint_properties', '{joint_name: swing}')['position'][0]
            slider = ros.service('/gazebo/get_model_state', '{model_name: slider}')['pose']['position']['x']
            return now, swing, slider - slider_start
        early = run_to(0.6)
        late = run_to(1.5)
        done = run_to(2.3)
        log = server.log()
    finally:
        ros.close()
    assert paused_time == 0.0, paused_time  # inserted before any step, as Gazebo's factory while paused
    assert sorted(names).count('ball') == 1 and len(names) == len(set(names)), names
    assert abs(placed['ball']['x'] - 0.0) < 1e-6 and abs(placed['ball_0']['x'] - 1.0) < 1e-6, placed
    assert abs(placed['renamed_box']['x'] - 2.0) < 1e-6 and abs(placed['crate']['x'] + 2.0) < 1e-6, placed
    assert 'broken' not in names and "nowhere" in log and 'Could not insert' in log, log
    # the joint linearly between its key frames: 0 -> 1.2 rad over the first second, back to 0.6 over
    # the next; the slider along the spline through 0, 0.5 and 1 m (test_gazebo_common has its values),
    # past the first key frame and short of the last at 1.5 s
    time, swing, moved = early
    assert abs(swing - 1.2 * time) < 0.02, early
    assert 0.0 < moved < 0.5, early
    time, swing, moved = late
    assert abs(swing - (1.2 - 0.6 * (time - 1.0))) < 0.02, late
    assert early[2] < 0.5 < moved < 1.0, (early, late)
    time, swing, moved = done  # both ended at 2 s: the joint where its last update put it, the slider 1 m on
    assert abs(swing - 0.6) < 0.02 and abs(moved - 1.0) < 0.01, done
    for what in ('arm joint', 'slider pose'):
        line = next((line for line in log.splitlines() if 'animate_model: %s animation complete at' % what in line),
                    None)
        assert line is not None, log
        assert 2.0 <= float(line.split(' at ')[1].split()[0]) < 2.01, line


def test_models_a_world_plugin_inserts_come_after_the_first_step_in_the_plant_from_python(
        catkin_make_workspace, tmp_path):
    """The plant from Python (no node) with the user's factory plugin in the world file: its
    insertions come at the end of the first step, named as Gazebo names them, where their poses put
    them; the one it cannot read is an error in the log and the world goes on."""
    workspace, env, _ = catkin_make_workspace
    world, models = factory_world(tmp_path)
    script = (
        "import json\n"
        "from tianracer_description import bullet_plant\n"
        "world = bullet_plant.World.from_file(%r)\n"
        "before = sorted(world.robots)\n"
        "world.step(1)\n"
        "print(json.dumps({'before': before, 'after': sorted(world.robots),\n"
        "                  'x': {n: world.robot(n).base_pose()[0] for n in ('ball', 'ball_0', 'renamed_box', 'crate')}}))\n"
        % str(world))
    done = subprocess.run(['/usr/bin/python3', '-c', script], env=dict(env, GAZEBO_MODEL_PATH=str(models)),
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    out = json.loads(done.stdout.strip().splitlines()[-1])
    assert out['before'] == ['arm', 'slider'], out
    assert out['after'] == ['arm', 'ball', 'ball_0', 'crate', 'renamed_box', 'slider'], out
    assert abs(out['x']['ball']) < 1e-3 and abs(out['x']['ball_0'] - 1.0) < 1e-3, out
    assert abs(out['x']['renamed_box'] - 2.0) < 1e-3 and abs(out['x']['crate'] + 2.0) < 1e-3, out
    assert 'nowhere' in done.stderr + done.stdout and 'the world goes on without it' in done.stderr + done.stdout, done


# A checkout of roboticsgroup_upatras_gazebo_plugins (github.com/roboticsgroup/...), as GRP_REPO is one
# of gazebo_ros_pkgs: its files stay out of this repository, so the test builds them where given.
ROBOTICSGROUP_REPO = os.environ.get('ROBOTICSGROUP_REPO')


@pytest.mark.slow
@pytest.mark.skipif(not ROBOTICSGROUP_REPO,
                    reason='ROBOTICSGROUP_REPO (a checkout of roboticsgroup_upatras_gazebo_plugins) is not set')
def test_roboticsgroups_own_mimic_joint_plugin_built_unchanged_moves_the_gripper_as_the_plants_own(
        install_space, tmp_path):
    """roboticsgroup's package (control_toolbox's PID, gazebo_ros, find_package(gazebo)) built with
    catkin_make on the install space, unchanged; its libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so,
    found on the workspace's library path, is loaded in place of the plant's own of that name and moves
    the gripper's second finger after the first by its PID, its gains from the parameter server, as
    test_mimic_joint_ros.py checks of the plant's own."""
    from plant_helpers import gripper
    from ros_harness import drive_mimic_gripper, start_plant
    workspace = tmp_path / 'rg_ws'
    status, output = run('git clone -q %s %s' % (ROBOTICSGROUP_REPO, workspace / 'src' / 'roboticsgroup_upatras_gazebo_plugins')
                         if os.path.isdir(os.path.join(ROBOTICSGROUP_REPO, 'objects')) or
                         os.path.isdir(os.path.join(ROBOTICSGROUP_REPO, '.git'))
                         else 'mkdir -p src && cp -r %s src/' % ROBOTICSGROUP_REPO, cwd=tmp_path)
    assert status == 0, output
    status, output = run('source %s/setup.bash && catkin_make' % install_space, cwd=workspace)
    assert status == 0, output
    env = sourced(workspace / 'devel' / 'setup.bash')
    urdf = gripper(hasPID='mimic_gains').replace('libroboticsgroup_gazebo_mimic_joint_plugin.so',
                                                 'libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so')
    (tmp_path / 'gripper.urdf').write_text(urdf)
    ros = RosSystem(str(tmp_path), base_env=env)
    try:
        plant = start_plant(ros)
        seen = drive_mimic_gripper(ros, plant, tmp_path / 'gripper.urdf')
        log = plant.log()
    finally:
        ros.close()
    assert 'MimicJointPlugin loaded! Joint: "finger_joint", Mimic joint: "finger_mimic_joint"' in log, log
    assert seen['finger_left'] == pytest.approx(0.01 + 0.03, abs=1e-3), 'the controller moved the first finger'
    assert seen['finger_right'] == pytest.approx(-0.01 - 0.03, abs=1e-3), 'upstream\'s PID the second'
