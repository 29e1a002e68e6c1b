"""Until COUNT controllers run in NAMESPACE's controller manager, polled every 20 ms (the harness's
RosSystem.wait_for_controllers):

    wait_for_controllers.py NAMESPACE COUNT

prints true on its last line once they do."""
import json, sys, time, rospy
from controller_manager_msgs.srv import ListControllers
name = '%s/controller_manager/list_controllers' % sys.argv[1]
count = int(sys.argv[2])
while True:
    try:
        rospy.wait_for_service(name, 0.05)
        if [c.state for c in rospy.ServiceProxy(name, ListControllers)().controller].count('running') == count:
            break
    except (rospy.ROSException, rospy.ServiceException):
        pass
    time.sleep(0.02)
print(json.dumps(True))
