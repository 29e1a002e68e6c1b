"""The car an environment races: any URDF car driven by the tutorial's four joint controllers, spawned
into a world of the plant with the tutorial's YAML, and an action turned into their commands through
the converter's Ackermann conversion (ackermann.py, as cmdvel2gazebo.py does it).

The default car is the tutorial's Tianracer with its IMU (xacro imu:=true). For render_mode
"rgb_array" a chase camera is added to the car's URDF: a camera sensor like the car's own, on a link
fixed behind and above its root link, looking at it.
"""
import functools
import math

import numpy as np
import yaml

from tianracer_description import bullet_plant
from tianracer_description.ackermann import max_ideal_steering, wheel_command_rows
from tianracer_description.tianracer import (CONFIG_YAML, MODEL_XACRO, REAR_WHEEL_CONTROLLERS, STEERING_CONTROLLERS,
                                             STEERING_JOINTS, TUTORIAL_CONTROLLERS, run_xacro)
from tianracer_description.urdf_geometry import UrdfModel, ackermann_geometry

# The commands' columns: the rear wheels' speeds (rad/s), then the steering hinges' angles (rad).
COMMAND_CONTROLLERS = REAR_WHEEL_CONTROLLERS + STEERING_CONTROLLERS
LIDAR, IMU, CHASE_CAMERA = 'lidar', 'imu', 'chase_camera'
CHASE_CAMERA_RATE = 30.0  # Hz
CHASE_CAMERA_SIZE = (320, 240)  # width, height


@functools.lru_cache(maxsize=None)
def tianracer_with_imu():
    """The tutorial's car with its IMU, as xacro expands urdf/tianracer_description.xacro imu:=true."""
    result = run_xacro(MODEL_XACRO, 'imu:=true')
    if result.returncode != 0:
        raise RuntimeError('xacro failed on %s: %s' % (MODEL_XACRO, result.stderr.strip()))
    return result.stdout


@functools.lru_cache(maxsize=None)
def tutorial_controllers():
    """config/smart_control_config.yaml, as `rosparam load` reads it."""
    with open(CONFIG_YAML) as f:
        return yaml.safe_load(f)


def with_chase_camera(urdf):
    """The URDF with a camera fixed 0.9 m behind and 0.45 m above its root link, pitched down at it."""
    width, height = CHASE_CAMERA_SIZE
    camera = f"""
  <link name="chase_camera_link"/>
  <joint name="chase_camera_joint" type="fixed">
    <parent link="{UrdfModel(urdf).root_link()}"/>
    <child link="chase_camera_link"/>
    <origin xyz="-0.9 0 0.45" rpy="0 0.42 0"/>
  </joint>
  <gazebo reference="chase_camera_link">
    <sensor type="camera" name="{CHASE_CAMERA}">
      <update_rate>{CHASE_CAMERA_RATE}</update_rate>
      <camera>
        <horizontal_fov>1.2</horizontal_fov>
        <image><width>{width}</width><height>{height}</height><format>R8G8B8</format></image>
        <clip><near>0.05</near><far>30</far></clip>
      </camera>
    </sensor>
  </gazebo>
</robot>"""
    end = urdf.rindex('</robot>')
    return urdf[:end] + camera + urdf[end + len('</robot>'):]


class CarModel:
    """What the environments know of a car: its URDF, its controllers' YAML, its Ackermann geometry
    measured from the URDF, its sensors' names, and the largest speed an action asks for."""

    def __init__(self, urdf=None, controllers=None, max_speed=2.0, lidar=LIDAR, imu=IMU):
        self.urdf = urdf or tianracer_with_imu()
        self.controllers = controllers or tutorial_controllers()
        self.geometry = ackermann_geometry(self.urdf)
        self.max_steering = max_ideal_steering(self.geometry.wheelbase, self.geometry.front_track,
                                               self.geometry.max_steer)
        if not (math.isfinite(max_speed) and max_speed > 0):
            raise ValueError('max_speed is a speed in m/s above 0; got %r' % (max_speed,))
        self.max_speed = float(max_speed)
        self._largest = np.array([self.max_steering, self.max_speed])  # what an action of 1 asks for
        self.lidar, self.imu = lidar, imu

    def commands(self, actions):
        """Actions (a row of steering, speed per car, each in [-1, 1] of the car's largest) as the four
        controllers' commands, a row per car in COMMAND_CONTROLLERS' order: the converter's
        wheel_commands (as rows)."""
        # wheel_command_rows holds the steering within [-max_steering, max_steering]; the speed is held here
        scaled = np.asarray(actions, np.float64).reshape(-1, 2) * self._largest
        speed = np.minimum(np.maximum(scaled[:, 1], -self.max_speed), self.max_speed)
        g = self.geometry
        return wheel_command_rows(speed, scaled[:, 0], g.wheelbase, g.rear_track, g.front_track, g.wheel_radius,
                                  self.max_steering)

    def spawn(self, world, name, pose, chase_camera=False):
        """The car in `world` at pose (x, y, yaw) with its controllers running (the spawner's)."""
        x, y, yaw = pose
        robot = world.spawn(with_chase_camera(self.urdf) if chase_camera else self.urdf, name,
                            pose=(x, y, 0.0, 0.0, 0.0, yaw))
        loaded, ok = robot.controller_manager.spawn(list(TUTORIAL_CONTROLLERS))
        if not ok:
            raise RuntimeError('the controllers did not start for %s: %s' % (name, world.messages()[-5:]))
        if chase_camera:
            robot.enable_sensor(CHASE_CAMERA)
        return robot

    def bind(self, batch, index, world, robot, centerline=None):
        """Car `index` of a bullet_plant.CarBatch is this car, `robot` in `world`, measured along
        `centerline` (a Centerline, or None)."""
        batch.set(index, world, robot, list(COMMAND_CONTROLLERS), self.lidar, self.imu or '', list(STEERING_JOINTS),
                  centerline)


def new_world(world_file, controllers, noise_seed=0):
    """A world of the plant from a world file (None: an empty one), with the controllers' YAML loaded,
    quiet, its sensors' noise seeded by `noise_seed` (0: by their names alone)."""
    world = bullet_plant.World.from_file(world_file) if world_file else bullet_plant.World()
    world.noise_seed = noise_seed
    world.echo = False
    world.load_params(controllers)
    return world
