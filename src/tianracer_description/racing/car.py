"""The car an environment races: any URDF car driven by the tutorial's four joint controllers, spawned
into a world of the plant with the tutorial's YAML, and an action turned into their commands through
the converter's Ackermann conversion (in bullet_plant.CarBatch.drive, the C++ that cmdvel2gazebo.py's
conversion calls too: ackermann.py).

The default car is the tutorial's Tianracer with its IMU (xacro imu:=true). Its parameters (CAR_PARAMS)
may differ car by car, for domain randomisation: its mass and its tyres' friction are written into the
URDF it is spawned from, its largest speed and steering are what an action of 1 asks for. For render_mode
"rgb_array" a chase camera is added to the car's URDF: a camera sensor like the car's own, on a link
fixed behind and above its root link, looking at it.
"""
import collections
import functools
import math
import xml.etree.ElementTree as ET

import yaml

from tianracer_description import bullet_plant
from tianracer_description.ackermann import max_ideal_steering
from tianracer_description.tianracer import (CONFIG_YAML, MODEL_XACRO, REAR_WHEEL_CONTROLLERS, STEERING_CONTROLLERS,
                                             STEERING_JOINTS, TUTORIAL_CONTROLLERS, run_xacro)
from tianracer_description.urdf_geometry import DEFAULT_JOINTS, UrdfModel, ackermann_geometry

# The commands' columns: the rear wheels' speeds (rad/s), then the steering hinges' angles (rad).
COMMAND_CONTROLLERS = REAR_WHEEL_CONTROLLERS + STEERING_CONTROLLERS
LIDAR, IMU, CHASE_CAMERA = 'lidar', 'imu', 'chase_camera'
CHASE_CAMERA_RATE = 30.0  # Hz
CHASE_CAMERA_SIZE = (320, 240)  # width, height
# A car's parameters, which reset(options={'car_params': ...}) may set car by car: the car's total mass
# (kg), its tyres' friction coefficient, and the speed (m/s) and steering angle (rad) an action of 1
# asks for.
CAR_PARAMS = ('mass', 'mu', 'max_speed', 'max_steering')
TYRE_JOINTS = ('left_rear_wheel', 'right_rear_wheel', 'left_front_wheel', 'right_front_wheel')  # DEFAULT_JOINTS' roles
GAZEBO_DEFAULT_MU = 1.0  # a surface's friction where its <gazebo> gives none
SPAWN_URDFS_KEPT = 16  # the URDFs of the last parameters spawned, kept for the next reset


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


def urdf_mass(urdf):
    """The total of a URDF's links' masses (kg)."""
    return sum(float(mass.get('value')) for mass in ET.fromstring(urdf).iter('mass'))


def tyre_links(urdf):
    """The links of the four wheels, the children of DEFAULT_JOINTS' wheel joints."""
    model = UrdfModel(urdf)
    return [model.joint(DEFAULT_JOINTS[role]).find('child').get('link') for role in TYRE_JOINTS]


def urdf_tyre_mu(urdf):
    """The friction coefficient of the tyres as the URDF gives it (the smallest of their <mu1> and
    <mu2>; Gazebo's 1 where it gives none)."""
    root, tyres = ET.fromstring(urdf), set(tyre_links(urdf))
    mus = [float(element.text) for gazebo in root.findall('gazebo') if gazebo.get('reference') in tyres
           for element in gazebo if element.tag in ('mu1', 'mu2')]
    return min(mus) if mus else GAZEBO_DEFAULT_MU


def urdf_with_mass_and_mu(urdf, mass, mu):
    """The URDF with every link's mass and inertia scaled so that the car weighs `mass` (kg; its centre
    of mass and its inertia's shape stay), and its tyres' <mu1> and <mu2> set to `mu`."""
    root, tyres = ET.fromstring(urdf), set(tyre_links(urdf))
    scale = mass / urdf_mass(urdf)
    for inertial in root.iter('inertial'):
        for element in inertial:
            if element.tag == 'mass':
                element.set('value', repr(float(element.get('value')) * scale))
            elif element.tag == 'inertia':
                for key, value in element.attrib.items():
                    element.set(key, repr(float(value) * scale))
    found = set()
    for gazebo in root.findall('gazebo'):
        if gazebo.get('reference') in tyres:
            found.add(gazebo.get('reference'))
            for tag in ('mu1', 'mu2'):
                element = gazebo.find(tag)
                if element is None:
                    element = ET.SubElement(gazebo, tag)
                element.text = repr(float(mu))
    for link in tyres - found:
        gazebo = ET.SubElement(root, 'gazebo', reference=link)
        for tag in ('mu1', 'mu2'):
            ET.SubElement(gazebo, tag).text = repr(float(mu))
    return ET.tostring(root, encoding='unicode')


class CarModel:
    """What the environments know of a car: its URDF, its controllers' YAML, its Ackermann geometry
    measured from the URDF, its sensors' names, and the largest speed an action asks for; and its
    parameters (CAR_PARAMS), the defaults and the ranges a car's may take."""

    def __init__(self, urdf=None, controllers=None, max_speed=2.0, lidar=LIDAR, imu=IMU):
        self.urdf = urdf or tianracer_with_imu()
        self.controllers = controllers or tutorial_controllers()
        self.geometry = ackermann_geometry(self.urdf)
        self.max_steering = max_ideal_steering(self.geometry.wheelbase, self.geometry.front_track,
                                               self.geometry.max_steer)
        if not (math.isfinite(max_speed) and max_speed > 0):
            raise ValueError('max_speed is a speed in m/s above 0; got %r' % (max_speed,))
        self.max_speed = float(max_speed)
        self.lidar, self.imu = lidar, imu
        self.mass, self.mu = urdf_mass(self.urdf), urdf_tyre_mu(self.urdf)
        # (mass, mu, chase_camera): the URDF spawned, the newest SPAWN_URDFS_KEPT (domain randomisation
        # draws a new mass and mu at every reset: kept all, they would grow without end)
        self._urdfs = collections.OrderedDict()

    def default_params(self):
        """The car's parameters as its URDF and max_speed give them (a dict of CAR_PARAMS)."""
        return {'mass': self.mass, 'mu': self.mu, 'max_speed': self.max_speed, 'max_steering': self.max_steering}

    def params(self, given, ground_mu=math.inf):
        """The car's parameters: `given` (a dict of some of CAR_PARAMS, or None), the defaults for the
        rest. ValueError names a parameter that is not one, or one out of its range: mass (kg) and
        max_speed (m/s) above 0, mu in (0, ground_mu] (a contact takes the smaller of the two surfaces'
        friction, so more than the ground's changes nothing), max_steering in (0, the car's largest]."""
        given = dict(given or {})
        unknown = sorted(set(given) - set(CAR_PARAMS))
        if unknown:
            raise ValueError('car_params has no %s; a car\'s parameters are %s' % (', '.join(unknown), ', '.join(CAR_PARAMS)))
        ranges = {'mass': (0.0, math.inf, 'kg'), 'mu': (0.0, ground_mu, ''), 'max_speed': (0.0, math.inf, 'm/s'),
                  'max_steering': (0.0, self.max_steering, 'rad')}
        params = self.default_params()
        for name, value in given.items():
            low, high, unit = ranges[name]
            try:
                value = float(value)
            except (TypeError, ValueError):
                raise ValueError('car_params %s is a number; got %r' % (name, value)) from None
            if not (low < value <= high and math.isfinite(value)):
                raise ValueError('car_params %s is in (%g, %g]%s; got %r' % (name, low, high, ' ' + unit if unit else '',
                                                                            value))
            params[name] = value
        return params

    def spawn_urdf(self, params=None, chase_camera=False):
        """The URDF a car of these parameters (None: the defaults) is spawned from, made once."""
        mass, mu = (self.mass, self.mu) if params is None else (params['mass'], params['mu'])
        key = (mass, mu, chase_camera)
        if key in self._urdfs:
            self._urdfs.move_to_end(key)
        else:
            urdf = self.urdf if (mass, mu) == (self.mass, self.mu) else urdf_with_mass_and_mu(self.urdf, mass, mu)
            self._urdfs[key] = with_chase_camera(urdf) if chase_camera else urdf
            if len(self._urdfs) > SPAWN_URDFS_KEPT:
                self._urdfs.popitem(last=False)
        return self._urdfs[key]

    def spawn(self, world, name, pose, chase_camera=False, params=None):
        """The car in `world` at pose (x, y, yaw), on what is under it there (standing_height), with its
        controllers running (the spawner's), its mass and tyres' friction `params`' (None: the URDF's)."""
        x, y, yaw = pose
        z = standing_height(world, x, y)
        robot = world.spawn(self.spawn_urdf(params, chase_camera), name, pose=(x, y, z, 0.0, 0.0, yaw))
        loaded, ok = robot.controller_manager.spawn(list(TUTORIAL_CONTROLLERS))
        if not ok:
            raise RuntimeError('the controllers did not start for %s: %s' % (name, world.messages()[-5:]))
        if chase_camera:
            robot.enable_sensor(CHASE_CAMERA)
        return robot

    def bind(self, batch, index, world, robot, centerline=None, params=None):
        """Car `index` of a bullet_plant.CarBatch is this car, `robot` in `world`, measured along
        `centerline` (a Centerline, or None), driven by actions (CarBatch.drive: steering and speed, each
        a share of the car's largest, through its Ackermann geometry) within `params`' max_steering and
        max_speed (None: the model's)."""
        batch.set(index, world, robot, list(COMMAND_CONTROLLERS), self.lidar, self.imu or '', list(STEERING_JOINTS),
                  centerline)
        params = params or self.default_params()
        g = self.geometry
        batch.set_drive(index, g.wheelbase, g.rear_track, g.front_track, g.wheel_radius, params['max_steering'],
                        params['max_speed'])


# How far above a start the car looks down for what it stands on, m.
STANDING_PROBE = 1.0


def standing_height(world, x, y):
    """The height of the first surface under (x, y) within STANDING_PROBE m up or down (the ground plane at
    0, a track's floor link or floor mesh above it); 0 where there is none."""
    below = world.cast_ray((x, y, STANDING_PROBE), (0.0, 0.0, -1.0), 2 * STANDING_PROBE)
    return STANDING_PROBE - below if math.isfinite(below) else 0.0


def new_world(world, controllers, noise_seed=0, time_step=None):
    """A world of the plant from a world file, or a bullet_plant.WorldDescription (a world file parsed
    once), or None (an empty world), with the controllers' YAML loaded, quiet, its sensors' noise
    seeded by `noise_seed` (0: by their names alone), its physics step `time_step` s (None: the world
    file's <max_step_size>)."""
    if isinstance(world, bullet_plant.WorldDescription):
        world = bullet_plant.World(world)
    else:
        world = bullet_plant.World.from_file(world) if world else bullet_plant.World()
    if time_step is not None:
        world.time_step = time_step
    world.noise_seed = noise_seed
    world.echo = False
    world.load_params(controllers)
    return world
