#!/usr/bin/python3
# -*- coding: utf-8 -*-
"""Keyboard teleoperation of the Tianracer: the tutorial's teleop.py in Python 3.

Publishes geometry_msgs/Twist on /tianracer/cmd_vel. angular.z is what cmdvel2gazebo.py reads as the
steering angle (its default ~angular_mode), so `turn` is in radians of steering.

Kept from the tutorial: the keys, the 10 % speed/turn scaling, the ramping towards the target and the
stop keys. Fixed: Python 3 (`print e` hid every error behind a NameError), the terminal is restored
and a zero Twist published on every way out, a clear message when stdin is not a terminal, and
defaults for this car (the tutorial's speed 10 is 10 m/s).

Private parameters: ~speed (m/s, default 1.0), ~turn (rad, default 0.5).
"""
import select
import sys
import termios
import tty

import rospy
from geometry_msgs.msg import Twist

msg = """
Control the Tianracer!
---------------------------
Moving around:
   u    i    o
   j    k    l
   m    ,    .

q/z : increase/decrease max speeds by 10%
w/x : increase/decrease only linear speed by 10%
e/c : increase/decrease only angular speed by 10%
space key, k : force stop
anything else : stop smoothly

CTRL-C to quit
"""

# key: (direction of speed, direction of turn)
moveBindings = {
    'i': (1, 0),
    'o': (1, -1),
    'j': (0, 1),
    'l': (0, -1),
    'u': (1, 1),
    ',': (-1, 0),
    '.': (-1, 1),
    'm': (-1, -1),
}

# key: (factor on speed, factor on turn)
speedBindings = {
    'q': (1.1, 1.1),
    'z': (.9, .9),
    'w': (1.1, 1),
    'x': (.9, 1),
    'e': (1, 1.1),
    'c': (1, .9),
}

SPEED_RAMP = 0.02    # m/s per key poll (the tutorial's)
TURN_RAMP = 0.1      # rad per key poll (the tutorial's)
KEY_TIMEOUT = 0.1    # s a poll waits for a key
CTRL_C = '\x03'


def getKey(settings):
    tty.setraw(sys.stdin.fileno())
    try:
        rlist, _, _ = select.select([sys.stdin], [], [], KEY_TIMEOUT)
        key = sys.stdin.read(1) if rlist else ''
    finally:
        termios.tcsetattr(sys.stdin, termios.TCSADRAIN, settings)
    return key


def vels(speed, turn):
    return "currently:\tspeed %s\tturn %s " % (speed, turn)


def ramp(current, target, step):
    if target > current:
        return min(target, current + step)
    if target < current:
        return max(target, current - step)
    return target


def teleop(pub, settings, speed, turn):
    x = 0
    th = 0
    status = 0
    count = 0
    control_speed = 0.0
    control_turn = 0.0
    print(msg)
    print(vels(speed, turn))
    while not rospy.is_shutdown():
        key = getKey(settings)
        # 运动控制方向键(1:正方向,-1负方向)
        if key in moveBindings:
            x, th = moveBindings[key]
            count = 0
        # 速度修改键
        elif key in speedBindings:
            speed = speed * speedBindings[key][0]  # 线速度增加0.1倍
            turn = turn * speedBindings[key][1]    # 角速度增加0.1倍
            count = 0
            print(vels(speed, turn))
            if status == 14:
                print(msg)
            status = (status + 1) % 15
        # 停止键
        elif key == ' ' or key == 'k':
            x = 0
            th = 0
            control_speed = 0.0
            control_turn = 0.0
        else:
            count = count + 1
            if count > 4:
                x = 0
                th = 0
            if key == CTRL_C:
                break

        # 目标速度=速度值*方向值, 速度限位,防止速度增减过快
        control_speed = ramp(control_speed, speed * x, SPEED_RAMP)
        control_turn = ramp(control_turn, turn * th, TURN_RAMP)

        # 创建并发布twist消息
        twist = Twist()
        twist.linear.x = control_speed
        twist.angular.z = control_turn
        pub.publish(twist)


def main():
    if not sys.stdin.isatty():
        sys.exit("teleop.py reads single key presses from a terminal, and its standard input is not one. "
                 "Run it in a terminal: rosrun tianracer_description teleop.py")
    settings = termios.tcgetattr(sys.stdin)
    rospy.init_node('carsmart_teleop')
    pub = rospy.Publisher('/tianracer/cmd_vel', Twist, queue_size=5)
    # A shutdown from ROS (rosnode kill, SIGTERM) stops the car too: hooks run before rospy closes topics.
    rospy.on_shutdown(lambda: pub.publish(Twist()))
    try:
        teleop(pub, settings, rospy.get_param('~speed', 1.0), rospy.get_param('~turn', 0.5))
    except Exception as e:
        print(e)
    finally:
        termios.tcsetattr(sys.stdin, termios.TCSADRAIN, settings)
        if not rospy.is_shutdown():
            pub.publish(Twist())


if __name__ == "__main__":
    main()
