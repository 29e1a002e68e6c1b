"""What a Gazebo model plugin costs the plant per step, counted: gazebo_ros_pkgs' diff drive as the
plant's own (src/plant/gazebo_plugins/gazebo_ros_diff_drive.cpp) against the same plugin built from
upstream's source against the plant's Gazebo 11 API (`--upstream-lib DIR`: a folder holding
upstream's libgazebo_ros_diff_drive.so, which the plant then loads in place of its own, as Gazebo
loads the file it finds).

The world: a two-wheeled robot in SDF with the diff drive plugin (wheels 0.066 m across, 0.16 m
apart, odometry at 30 Hz, as turtlebot3's) on a ground plane, 1 ms steps as fast as the plant goes.
The node runs `STEPS_SHORT` and `STEPS_LONG` iterations (gzserver's --iters) under `valgrind
--tool=callgrind`, counting inside the world's step only, against a ROS master of its own; (Ir(long)
- Ir(short)) / (long - short) is one step with the first steps' settling subtracted. The same
without the plugin gives the robot's own cost: the plugin's is the difference (the joint motors it
drives included). Instruction counts do not depend on the machine's load.

    python3 bench/gazebo_plugin_cost.py [--upstream-lib DIR]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from ros_harness import RosSystem  # noqa: E402

STEPS_SHORT, STEPS_LONG = 300, 1300
# Only the world's step is counted (the plugins' updates and what they publish run in it): the
# node's ROS threads do work by the wall clock, which callgrind stretches some fifty times.
STEP_FUNCTION = 'bullet_plant::World::step(int)'


DIFF_DRIVE = '''
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <leftJoint>left_wheel_joint</leftJoint>
        <rightJoint>right_wheel_joint</rightJoint>
        <wheelSeparation>0.160</wheelSeparation>
        <wheelDiameter>0.066</wheelDiameter>
        <wheelTorque>20</wheelTorque>
        <wheelAcceleration>1</wheelAcceleration>
        <updateRate>30</updateRate>
        <commandTopic>cmd_vel</commandTopic>
        <odometryTopic>odom</odometryTopic>
        <odometryFrame>odom</odometryFrame>
        <robotBaseFrame>base_link</robotBaseFrame>
        <odometrySource>world</odometrySource>
        <publishWheelTF>false</publishWheelTF>
        <publishWheelJointState>false</publishWheelJointState>
        <publishOdomTF>true</publishOdomTF>
        <publishTf>1</publishTf>
      </plugin>'''


def wheel(name, y):
    return '''
      <link name="{0}">
        <pose>0 {1} 0.033 -1.5708 0 0</pose>
        <inertial><mass>0.03</mass><inertia><ixx>1e-5</ixx><iyy>1e-5</iyy><izz>2e-5</izz></inertia></inertial>
        <collision name="collision"><geometry><cylinder><radius>0.033</radius><length>0.018</length></cylinder></geometry></collision>
      </link>
      <joint name="{0}_joint" type="revolute">
        <parent>base_link</parent><child>{0}</child>
        <axis><xyz>0 0 1</xyz></axis>
      </joint>'''.format(name, y)


def world(plugin):
    return '''<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <physics type="ode"><max_step_size>0.001</max_step_size><real_time_update_rate>0</real_time_update_rate></physics>
    <model name="ground_plane">
      <static>true</static>
      <link name="link"><collision name="collision"><geometry><plane><normal>0 0 1</normal><size>20 20</size></plane></geometry></collision></link>
    </model>
    <model name="diff_bot">
      <pose>0 0 0.01 0 0 0</pose>
      <link name="base_link">
        <pose>0 0 0.05 0 0 0</pose>
        <inertial><mass>1.0</mass><inertia><ixx>0.004</ixx><iyy>0.004</iyy><izz>0.006</izz></inertia></inertial>
        <collision name="collision"><geometry><box><size>0.14 0.12 0.06</size></box></geometry></collision>
      </link>
      <link name="caster">
        <pose>-0.06 0 0.01 0 0 0</pose>
        <inertial><mass>0.01</mass><inertia><ixx>1e-6</ixx><iyy>1e-6</iyy><izz>1e-6</izz></inertia></inertial>
        <collision name="collision"><geometry><sphere><radius>0.01</radius></sphere></geometry>
          <surface><friction><ode><mu>0</mu><mu2>0</mu2></ode></friction></surface></collision>
      </link>
      <joint name="caster_joint" type="fixed"><parent>base_link</parent><child>caster</child></joint>''' + \
        wheel('left_wheel', 0.08) + wheel('right_wheel', -0.08) + plugin + '''
    </model>
  </world>
</sdf>
'''


def plant_executable():
    from catkin.find_in_workspaces import find_in_workspaces
    found = find_in_workspaces(['libexec'], project='tianracer_description', path='bullet_plant', first_match_only=True)
    if not found:
        raise SystemExit('gazebo_plugin_cost: no bullet_plant in the workspace: run `make build` and source it')
    return found[0]


def instructions(world_file, steps, plugin_path, workdir):
    """Ir of the node's world steps running `steps` iterations of `world_file`."""
    out = os.path.join(workdir, 'callgrind.%d.out' % steps)
    os.makedirs(os.path.join(workdir, 'ros%d' % steps))
    ros = RosSystem(os.path.join(workdir, 'ros%d' % steps))
    try:
        ros.env['GAZEBO_PLUGIN_PATH'] = plugin_path
        ros.set_param('/use_sim_time', True)
        node = ros.start(['valgrind', '--tool=callgrind', '--toggle-collect=' + STEP_FUNCTION,
                          '--callgrind-out-file=' + out, plant_executable(),
                          '_world_name:=' + world_file, '_paused:=false', '_iterations:=%d' % steps,
                          '_lockstep:=false'], 'plant')
        if node.popen.wait(timeout=1800) != 0:
            raise SystemExit('gazebo_plugin_cost: the node exited %d:\n%s' % (node.popen.returncode, node.log()[-3000:]))
    finally:
        ros.close()
    with open(out) as f:
        return int(re.search(r'^summary: (\d+)', f.read(), re.M).group(1))


def per_step(world_text, plugin_path, workdir, label):
    path = os.path.join(workdir, label + '.world')
    with open(path, 'w') as f:
        f.write(world_text)
    short = instructions(path, STEPS_SHORT, plugin_path, os.path.join(workdir, label))
    long = instructions(path, STEPS_LONG, plugin_path, os.path.join(workdir, label))
    return (long - short) / (STEPS_LONG - STEPS_SHORT)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--upstream-lib', metavar='DIR',
                        help="a folder with upstream's libgazebo_ros_diff_drive.so built against the plant's API")
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        for label in ('none', 'own', 'upstream'):
            os.makedirs(os.path.join(workdir, label))
        none = per_step(world(''), '', workdir, 'none')
        own = per_step(world(DIFF_DRIVE), '', workdir, 'own')
        print('instructions per step: robot without a plugin %.0f; the plant\'s own diff drive %.0f (+%.0f)'
              % (none, own, own - none))
        if options.upstream_lib:
            library = os.path.join(os.path.abspath(options.upstream_lib), 'libgazebo_ros_diff_drive.so')
            if not os.path.isfile(library):
                raise SystemExit('gazebo_plugin_cost: no %s' % library)
            upstream = per_step(world(DIFF_DRIVE), os.path.abspath(options.upstream_lib), workdir, 'upstream')
            print('upstream\'s diff drive on the Gazebo API %.0f (+%.0f): %.2fx the plant\'s own plugin'
                  % (upstream, upstream - none, (upstream - none) / max(own - none, 1.0)))


if __name__ == '__main__':
    main()
