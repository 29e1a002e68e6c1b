"""Follow the gap, the F1TENTH community's baseline: steer for the deepest point of the widest opening
in the scan ahead, after blanking a bubble around the nearest obstacle, and slow down for the turn.

    policy = FollowTheGap(angle_min=-2.356, angle_increment=0.00436, max_steering=0.42)
    action = policy(observation)   # [steering, speed], each in [-1, 1], as the environments take them
"""
import math

import numpy as np


class FollowTheGap:
    def __init__(self, angle_min, angle_increment, max_steering, field_of_view=math.radians(180),
                 bubble_radius=0.35, gap_depth=1.0, horizon=4.0, straight_speed=1.0, turn_speed=0.5):
        """angle_min, angle_increment: the scan's (rad); max_steering: the steering angle an action of 1
        asks for (rad); field_of_view: how much of the scan ahead is looked at; bubble_radius: the
        car's clearance around the nearest obstacle (m); gap_depth: ranges beyond this are open (m);
        horizon: ranges are cut here (m); straight_speed, turn_speed: the speed action going straight
        and at full steering."""
        self.angle_min, self.angle_increment = angle_min, angle_increment
        self.max_steering = max_steering
        self.field_of_view = field_of_view
        self.bubble_radius, self.gap_depth, self.horizon = bubble_radius, gap_depth, horizon
        self.straight_speed, self.turn_speed = straight_speed, turn_speed

    @classmethod
    def for_env(cls, env, **settings):
        """The policy for an environment's car (RaceEnv, RaceVectorEnv or RaceParallelEnv, wrapped or not)."""
        env = getattr(env, 'unwrapped', env)
        return cls(env.lidar.angle_min, env.lidar.angle_increment, env.model.max_steering, **settings)

    def target_angle(self, scan):
        """The bearing (rad, left positive) of the point the car steers for."""
        angles = self.angle_min + self.angle_increment * np.arange(len(scan))
        ahead = np.abs(angles) <= self.field_of_view / 2
        ranges = np.minimum(np.asarray(scan, np.float64)[ahead], self.horizon)
        ranges = np.convolve(ranges, np.ones(5) / 5, mode='same')  # one noisy ray is not a gap
        angles = angles[ahead]
        nearest = int(np.argmin(ranges))
        # Blank the rays within the bubble around the nearest obstacle: the car cannot pass there.
        half_width = math.atan2(self.bubble_radius, max(ranges[nearest], 1e-3))
        ranges[np.abs(angles - angles[nearest]) <= half_width] = 0.0
        open_rays = np.concatenate([[False], ranges > self.gap_depth, [False]])
        edges = np.flatnonzero(np.diff(open_rays.astype(np.int8)))
        if len(edges) < 2:
            return float(angles[int(np.argmax(ranges))])  # no opening: the farthest ray
        starts, ends = edges[0::2], edges[1::2]
        widest = int(np.argmax(ends - starts))
        gap = slice(starts[widest], ends[widest])
        # The deepest point of the gap, and its middle, averaged: deep enough to go far, centred
        # enough not to cut the corner onto the inside wall.
        deepest = starts[widest] + int(np.argmax(ranges[gap]))
        middle = (starts[widest] + ends[widest] - 1) / 2
        return float(np.interp((deepest + middle) / 2, np.arange(len(angles)), angles))

    def __call__(self, observation):
        steering = float(np.clip(self.target_angle(observation['scan']) / self.max_steering, -1.0, 1.0))
        speed = self.straight_speed + (self.turn_speed - self.straight_speed) * abs(steering)
        return np.array([steering, speed], np.float32)
