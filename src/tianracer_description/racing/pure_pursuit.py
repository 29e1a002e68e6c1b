"""Pure pursuit, the F1TENTH community's waypoint follower: steer the rear axle onto the arc through
the point of the race line a lookahead distance ahead, at the race line's speed there.

    env = gymnasium.make('Tianracer-Map-v0', observe_pose=True)   # the policy reads the car's pose
    policy = PurePursuit.for_env(env)                              # the track's race line
    action = policy(observation)   # [steering, speed], each in [-1, 1], as the environments take them
"""
import math

import numpy as np

from tianracer_description.urdf_geometry import DEFAULT_JOINTS, UrdfModel


def pure_pursuit_steering(x, y, yaw, waypoints, lookahead, wheelbase):
    """(steering angle (rad, left positive), index of the waypoint nearest the rear axle) for a rear
    axle at (x, y) heading yaw, following the closed loop of `waypoints` (an (N, 2) array in the
    direction of driving): the arc through the axle, tangent to the heading, that meets the first
    waypoint `lookahead` metres away or more, ahead along the loop from the nearest one."""
    offsets = waypoints - (x, y)
    distances = np.hypot(offsets[:, 0], offsets[:, 1])
    nearest = int(np.argmin(distances))
    # the loop from the nearest waypoint on: the first one beyond the lookahead is the goal
    order = np.roll(np.arange(len(waypoints)), -nearest)
    beyond = np.flatnonzero(distances[order] >= lookahead)
    goal = order[beyond[0]] if len(beyond) else order[-1]
    dx, dy = offsets[goal]
    ahead = math.cos(yaw) * dx + math.sin(yaw) * dy
    left = -math.sin(yaw) * dx + math.cos(yaw) * dy
    reach = math.hypot(ahead, left)
    # the arc's curvature is 2 sin(alpha) / reach, alpha the goal's bearing; the bicycle's steering
    # angle for it is atan(wheelbase * curvature)
    return math.atan2(2.0 * wheelbase * left / reach, reach), nearest


class PurePursuit:
    def __init__(self, waypoints, wheelbase, max_steering, max_speed, speeds=None, speed=1.0, speed_scale=1.0,
                 lookahead=0.6, lookahead_gain=0.2, rear_axle=0.0):
        """waypoints: the line followed, (N, 2) points of a closed loop in the direction of driving;
        wheelbase (m); max_steering: the steering angle an action of 1 asks for (rad); max_speed: the
        speed an action of 1 asks for (m/s); speeds: the line's speed at each waypoint (m/s; None: the
        constant `speed`), times speed_scale; lookahead: metres ahead of the rear axle, plus
        lookahead_gain times the car's speed (m/s); rear_axle: where the rear axle is ahead of the
        pose the car reports (m; negative behind)."""
        self.waypoints = np.asarray(waypoints, np.float64)
        if self.waypoints.ndim != 2 or self.waypoints.shape[1] != 2 or len(self.waypoints) < 3:
            raise ValueError('waypoints are (N, 2) points of a closed loop, N >= 3; got shape %s'
                             % (self.waypoints.shape,))
        self.speeds = None if speeds is None else np.asarray(speeds, np.float64)
        if self.speeds is not None and self.speeds.shape != (len(self.waypoints),):
            raise ValueError('speeds has one speed per waypoint (%d); got shape %s'
                             % (len(self.waypoints), self.speeds.shape))
        self.wheelbase, self.max_steering, self.max_speed = wheelbase, max_steering, max_speed
        self.speed, self.speed_scale = speed, speed_scale
        self.lookahead, self.lookahead_gain, self.rear_axle = lookahead, lookahead_gain, rear_axle

    @classmethod
    def for_env(cls, env, **settings):
        """The policy for an environment's car (RaceEnv, RaceVectorEnv or RaceParallelEnv, wrapped or
        not, made with observe_pose=True) on its track's race line (its centre line where it has
        none) at the race line's speeds."""
        env = getattr(env, 'unwrapped', env)
        space = getattr(env, 'single_observation_space', None) or getattr(env, '_observation_space', None) \
            or env.observation_space
        if 'pose' not in space.spaces:
            raise ValueError('pure pursuit reads the car\'s pose: make the environment with observe_pose=True')
        geometry, track = env.model.geometry, env.track
        urdf = UrdfModel(env.model.urdf)
        rear_axle = (urdf.joint_position(DEFAULT_JOINTS['left_rear_wheel'])[0]
                     + urdf.joint_position(DEFAULT_JOINTS['right_rear_wheel'])[0]) / 2.0
        settings.setdefault('rear_axle', float(rear_axle))
        settings.setdefault('speeds', track.raceline_speeds)
        return cls(track.raceline, geometry.wheelbase, env.model.max_steering, env.model.max_speed, **settings)

    def __call__(self, observation):
        x, y, yaw = (float(v) for v in observation['pose'])
        speed = float(np.asarray(observation['speed']).reshape(-1)[0])
        lookahead = self.lookahead + self.lookahead_gain * max(speed, 0.0)
        steering, nearest = pure_pursuit_steering(x + self.rear_axle * math.cos(yaw), y + self.rear_axle * math.sin(yaw),
                                                  yaw, self.waypoints, lookahead, self.wheelbase)
        target = self.speed if self.speeds is None else self.speeds[nearest]
        return np.array([np.clip(steering / self.max_steering, -1.0, 1.0),
                         np.clip(target * self.speed_scale / self.max_speed, -1.0, 1.0)], np.float32)
