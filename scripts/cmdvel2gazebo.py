#!/usr/bin/python3
"""cmdvel2gazebo: the tutorial's Twist -> Ackermann converter, in Python 3.

Subscribes /tianracer/cmd_vel (geometry_msgs/Twist) and, for race car drivers, ~ackermann_topic
(ackermann_msgs/AckermannDriveStamped: drive.speed in m/s, drive.steering_angle in rad of the ideal
middle front wheel), and publishes, at 10 Hz, the two rear wheel speeds and the two steering angles
to the tutorial's four controllers. Without a command for 0.2 s it commands the wheels to 0 and the
steering straight (dead man's switch).

Kept from the tutorial: the class, topics, rate, timeout, geometry and clamping. Fixed: the wheel
speed is linear.x / wheel radius (the tutorial's `/ 0.3` belonged to the author's own model); the
geometry is read from robot_description; non-finite input is ignored; ~angular_mode chooses what
angular.z means.

Private parameters (defaults from robot_description):
  ~wheelbase, ~rear_track, ~front_track, ~wheel_radius (m), ~max_inside_steer (rad)
  ~angular_mode: steering_angle (default; the tutorial's) or yaw_rate (REP 103)
  ~ackermann_topic: /tianracer/ackermann_cmd_stamped ('' for none)
  ~timeout: 0.2 s; ~rate: 10 Hz
"""
import math

import rospy
from ackermann_msgs.msg import AckermannDriveStamped
from geometry_msgs.msg import Twist
from std_msgs.msg import Float64

from tianracer_description.ackermann import (STEERING_ANGLE, ideal_steering, max_ideal_steering,
                                             wheel_commands)
from tianracer_description.urdf_geometry import ackermann_geometry


class CmdVel2Gazebo:

    def __init__(self):
        rospy.init_node('cmdvel2gazebo', anonymous=True)

        self.load_geometry()
        self.angular_mode = rospy.get_param('~angular_mode', STEERING_ANGLE)
        ideal_steering(0.0, 0.0, self.angular_mode, self.L)  # refuses an unknown mode early

        rospy.Subscriber('/tianracer/cmd_vel', Twist, self.callback, queue_size=1)
        ackermann_topic = rospy.get_param('~ackermann_topic', '/tianracer/ackermann_cmd_stamped')
        if ackermann_topic:
            rospy.Subscriber(ackermann_topic, AckermannDriveStamped, self.ackermann_callback, queue_size=1)

        self.pub_steerL = rospy.Publisher('/tianracer/front_left_steering_position_controller/command', Float64, queue_size=1)
        self.pub_steerR = rospy.Publisher('/tianracer/front_right_steering_position_controller/command', Float64, queue_size=1)
        self.pub_rearL = rospy.Publisher('/tianracer/rear_left_velocity_controller/command', Float64, queue_size=1)
        self.pub_rearR = rospy.Publisher('/tianracer/rear_right_velocity_controller/command', Float64, queue_size=1)

        # initial velocity and tire angle are 0
        self.x = 0.0  # ground speed, m/s
        self.z = 0.0  # ideal middle front wheel angle, rad

        # how many seconds delay for the dead man's switch
        self.timeout = rospy.Duration.from_sec(rospy.get_param('~timeout', 0.2))
        self.lastMsg = rospy.Time.now()

        # maximum steering angle of the ideal middle wheel, when the inside wheel is at its limit
        self.maxsteer = max_ideal_steering(self.L, self.T_front, self.maxsteerInside)
        rospy.loginfo('cmdvel2gazebo: wheelbase %.4f m, tracks %.4f/%.4f m, wheel radius %.4f m, '
                      'max steering %.3f rad, angular.z as %s', self.L, self.T_rear, self.T_front,
                      self.wheel_radius, self.maxsteer, self.angular_mode)

        rate = rospy.Rate(rospy.get_param('~rate', 10.0))
        while not rospy.is_shutdown():
            self.publish()
            rate.sleep()

    def load_geometry(self):
        """The car's geometry: from robot_description, each value overridable by a private param."""
        measured = None
        if rospy.has_param('robot_description'):
            measured = ackermann_geometry(rospy.get_param('robot_description'))
        elif not all(rospy.has_param('~' + p) for p in ('wheelbase', 'rear_track', 'front_track', 'wheel_radius',
                                                         'max_inside_steer')):
            raise SystemExit('cmdvel2gazebo: no robot_description to read the geometry from; load it or set '
                             '~wheelbase, ~rear_track, ~front_track, ~wheel_radius and ~max_inside_steer')
        self.L = rospy.get_param('~wheelbase', measured and measured.wheelbase)
        self.T_rear = rospy.get_param('~rear_track', measured and measured.rear_track)
        self.T_front = rospy.get_param('~front_track', measured and measured.front_track)
        self.wheel_radius = rospy.get_param('~wheel_radius', measured and measured.wheel_radius)
        self.maxsteerInside = rospy.get_param('~max_inside_steer', measured and measured.max_steer)

    def callback(self, data):
        if not (math.isfinite(data.linear.x) and math.isfinite(data.angular.z)):
            rospy.logwarn_throttle(1.0, 'cmdvel2gazebo: ignored a Twist with non-finite linear.x or angular.z')
            return
        self.command(data.linear.x, ideal_steering(data.linear.x, data.angular.z, self.angular_mode, self.L))

    def ackermann_callback(self, data):
        if not (math.isfinite(data.drive.speed) and math.isfinite(data.drive.steering_angle)):
            rospy.logwarn_throttle(1.0, 'cmdvel2gazebo: ignored an AckermannDriveStamped with non-finite speed or '
                                   'steering_angle')
            return
        self.command(data.drive.speed, data.drive.steering_angle)

    def command(self, speed, steer):
        self.x = speed
        # constrain the ideal steering angle such that the ackermann steering is maxed out
        self.z = max(-self.maxsteer, min(self.maxsteer, steer))
        self.lastMsg = rospy.Time.now()

    def publish(self):
        # NOTE: the speed goes to 0 (and the wheels straight) only after the timeout without a Twist
        msgs_too_old = rospy.Time.now() - self.lastMsg > self.timeout
        if msgs_too_old:
            self.x = 0.0
            self.z = 0.0
        commands = wheel_commands(self.x, self.z, self.L, self.T_rear, self.T_front, self.wheel_radius, self.maxsteer)
        self.pub_rearL.publish(Float64(commands.rear_left))
        self.pub_rearR.publish(Float64(commands.rear_right))
        self.pub_steerL.publish(Float64(commands.steer_left))
        self.pub_steerR.publish(Float64(commands.steer_right))


if __name__ == '__main__':
    try:
        CmdVel2Gazebo()
    except rospy.ROSInterruptException:
        pass
