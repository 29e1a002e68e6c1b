#!/usr/bin/python3
"""A race car driver as Gazebo users write them: it reads the car's pose from /gazebo/link_states
(gazebo_msgs) and steers to a point with ackermann_msgs/AckermannDriveStamped on
/tianracer/ackermann_cmd_stamped (cmdvel2gazebo.py turns that into the four controller commands).
Exits 0 within ~tolerance of (~x, ~y), 1 after ~timeout wall seconds."""
import math
import sys
import time

import rospy
from ackermann_msgs.msg import AckermannDriveStamped
from gazebo_msgs.msg import LinkStates

LINK = 'tianracer::base_link'


def main():
    rospy.init_node('drive_to_point')
    goal = (rospy.get_param('~x'), rospy.get_param('~y'))
    tolerance, timeout = rospy.get_param('~tolerance', 0.25), rospy.get_param('~timeout', 40.0)
    pose = {}

    def on_links(msg):
        if LINK in msg.name:
            p = msg.pose[msg.name.index(LINK)]
            q = p.orientation
            pose['now'] = (p.position.x, p.position.y,
                           math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z)))

    rospy.Subscriber('/gazebo/link_states', LinkStates, on_links, queue_size=1)
    pub = rospy.Publisher('/tianracer/ackermann_cmd_stamped', AckermannDriveStamped, queue_size=1)
    command = AckermannDriveStamped()
    end = time.monotonic() + timeout
    while not rospy.is_shutdown() and time.monotonic() < end:
        if 'now' in pose:
            x, y, yaw = pose['now']
            distance = math.hypot(goal[0] - x, goal[1] - y)
            if distance < tolerance:
                pub.publish(AckermannDriveStamped())  # stop
                print('reached (%.3f, %.3f), %.3f m from the goal' % (x, y, distance))
                return 0
            error = math.atan2(goal[1] - y, goal[0] - x) - yaw
            error = math.atan2(math.sin(error), math.cos(error))
            command.header.stamp = rospy.Time.now()
            command.drive.speed = 0.6
            command.drive.steering_angle = max(-0.5, min(0.5, 1.5 * error))
            pub.publish(command)
        time.sleep(0.05)
    print('did not reach the goal; last pose %s' % (pose.get('now'),))
    return 1


if __name__ == '__main__':
    sys.exit(main())
