"""The tutorial's car and files, named once for the tests, benchmarks and tools: the package's paths,
the five controllers of config/smart_control_config.yaml, the joints they drive and the car's URDF
as xacro expands it."""
import functools
import os
import subprocess

import rospkg


@functools.lru_cache(maxsize=None)
def package_path(package='tianracer_description'):
    """Where rospack finds a package (the workspace must be sourced: source .ws/devel/setup.bash)."""
    try:
        return rospkg.RosPack().get_path(package)
    except rospkg.ResourceNotFound:
        raise RuntimeError("rospack cannot find '%s': build and source the workspace "
                           "(make build; source .ws/devel/setup.bash)" % package) from None


PACKAGE = package_path()
CONFIG_YAML = os.path.join(PACKAGE, 'config', 'smart_control_config.yaml')
MODEL_XACRO = os.path.join(PACKAGE, 'urdf', 'tianracer_description.xacro')
RACE_TRACK_WORLD = os.path.join(PACKAGE, 'worlds', 'race_track.world')
RACE_CIRCUIT_WORLD = os.path.join(PACKAGE, 'worlds', 'race_circuit.world')
# Our track in f1tenth's format (a map_server map, centre line and race line; tools/make_map_track.py).
PEANUT_MAP = os.path.join(PACKAGE, 'worlds', 'peanut_map.yaml')

# What the tutorial's control.launch hands the spawner, in its order.
TUTORIAL_CONTROLLERS = ('joint_state_controller', 'rear_right_velocity_controller', 'rear_left_velocity_controller',
                        'front_right_steering_position_controller', 'front_left_steering_position_controller')
REAR_WHEEL_CONTROLLERS = ('rear_left_velocity_controller', 'rear_right_velocity_controller')
STEERING_CONTROLLERS = ('front_left_steering_position_controller', 'front_right_steering_position_controller')
# The URDF's joints those controllers command, left before right.
REAR_WHEEL_JOINTS = ('left_rear_wheel_joint', 'right_rear_wheel_joint')
STEERING_JOINTS = ('left_steering_hinge_joint', 'right_steering_hinge_joint')


def run_xacro(xacro_file, *args):
    """xacro as a launch file runs it: $(find xacro)/xacro --inorder FILE (a CompletedProcess)."""
    return subprocess.run([os.path.join(package_path('xacro'), 'xacro'), '--inorder', xacro_file, *args],
                          capture_output=True, text=True)


@functools.lru_cache(maxsize=None)
def tianracer_urdf():
    """The car's URDF text, expanded from urdf/tianracer_description.xacro."""
    result = run_xacro(MODEL_XACRO)
    if result.returncode != 0:
        raise RuntimeError('xacro failed on %s: %s' % (MODEL_XACRO, result.stderr.strip()))
    return result.stdout
