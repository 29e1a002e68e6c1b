"""Calls to a controller manager's services that never hang, for the spawner and unspawner.

Not part of the controller_manager module: that one offers exactly ros_control's public functions,
so that the scripts also run with upstream's module first on PYTHONPATH (docs/interfaces.md
section 12). The scripts need more than upstream's functions give (a service namespace of their
own, calls with a time limit), and this is the one place for it.
"""
import threading
import time

import rospy


def service_name(service, namespace=''):
    """The name of one of the manager's services, e.g. 'load_controller'.

    With no namespace the name is relative ('controller_manager/load_controller') and resolves
    against the caller's namespace, as in ros_control; with one it is
    NAMESPACE/controller_manager/SERVICE.
    """
    if not namespace:
        return 'controller_manager/' + service
    return namespace.rstrip('/') + '/controller_manager/' + service


class ServiceTimeout(rospy.ServiceException):
    """The controller manager did not answer in time (busy, paused simulation, or hung)."""


def call_with_timeout(proxy, request, timeout=None):
    """proxy.call(request), waiting at most timeout seconds (wall clock) for the answer, and with
    no timeout (None) as long as it takes but no longer than the node runs.

    rospy service calls have no timeout: a manager that accepted the connection but never answers
    would keep the caller forever, even after Ctrl-C. The call runs in a daemon thread that is
    abandoned if it overstays, so the process can still exit. Any failure is raised as
    rospy.ServiceException (ServiceTimeout when time ran out).
    """
    outcome = {}

    def call():
        try:
            outcome['response'] = proxy.call(request)
        except Exception as error:  # handed to the caller below
            outcome['error'] = error

    worker = threading.Thread(target=call, name='call %s' % proxy.resolved_name, daemon=True)
    worker.start()
    deadline = None if timeout is None else time.monotonic() + timeout
    while worker.is_alive():
        if rospy.core.is_shutdown():
            raise rospy.ServiceException('gave up waiting for %s: the node is shut down'
                                         % proxy.resolved_name)
        wait = 0.05 if deadline is None else min(0.05, deadline - time.monotonic())
        if wait <= 0:
            raise ServiceTimeout('%s did not answer within %.2g s' % (proxy.resolved_name, timeout))
        worker.join(wait)
    if 'error' in outcome:
        error = outcome['error']
        if isinstance(error, rospy.ServiceException):
            raise error
        raise rospy.ServiceException('%s: %s' % (proxy.resolved_name, error))
    return outcome['response']
