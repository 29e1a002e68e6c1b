"""Calls the controller manager's ROS services (controller_manager_msgs), like ros_control's module.

The functions named like ros_control's (load_controller, unload_controller, start_controller,
stop_controller, list_controllers, list_controller_types, reload_libraries) serve the
`controller_manager` command: they wait for the service, call it, print what happened in the same
words as ros_control 0.20 and return True or False. Their service names are relative
(controller_manager/...), so ROS_NAMESPACE or __ns:= picks the manager.

service_name() and call_with_timeout() serve the spawner and unspawner, which must never hang on a
controller manager that is busy, paused or gone.
"""
import sys
import threading
import time

import rospy
from controller_manager_msgs.srv import (ListControllerTypes, ListControllerTypesRequest,
                                         ListControllers, ListControllersRequest, LoadController,
                                         LoadControllerRequest, ReloadControllerLibraries,
                                         ReloadControllerLibrariesRequest, SwitchController,
                                         SwitchControllerRequest, UnloadController,
                                         UnloadControllerRequest)

# How long the command waits quietly for a service before saying what it is waiting for.
_QUIET_WAIT = 3.0


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


def _call(service, service_class, request):
    """Waits for the manager's service (forever, as ros_control does) and calls it.

    Says on stderr what it waits for when the manager is slow to appear: a silent wait on a wrong
    namespace is the usual way this command seems to hang.
    """
    proxy = rospy.ServiceProxy(service_name(service), service_class)
    try:
        proxy.wait_for_service(_QUIET_WAIT)
    except rospy.ROSException:
        sys.stderr.write('Waiting for service %s: is the controller manager running, and in this '
                         'namespace (set ROS_NAMESPACE or add __ns:=/NAMESPACE)?\n'
                         % proxy.resolved_name)
        proxy.wait_for_service()
    return proxy.call(request)


def _report_failure(service, error):
    resolved_name = rospy.names.resolve_name(service_name(service))
    sys.stderr.write('Calling %s failed: %s\n' % (resolved_name, error))


def list_controller_types():
    """Prints the controller types the manager can load, one a line."""
    try:
        response = _call('list_controller_types', ListControllerTypes, ListControllerTypesRequest())
    except rospy.ServiceException as error:
        _report_failure('list_controller_types', error)
        return False
    for controller_type in response.types:
        print(controller_type)
    return True


def _controller_states():
    return _call('list_controllers', ListControllers, ListControllersRequest()).controller


def list_controllers():
    """Prints one line per loaded controller: 'name' - 'claimed interfaces' ( state )."""
    try:
        states = _controller_states()
    except rospy.ServiceException as error:
        _report_failure('list_controllers', error)
        return False
    if not states:
        print('No controllers are loaded in mechanism control')
    for state in states:
        # Each interface once, in the order claimed (ros_control uses a set: random order).
        interfaces = []
        for claimed in state.claimed_resources:
            if claimed.hardware_interface not in interfaces:
                interfaces.append(claimed.hardware_interface)
        print("'%s' - '%s' ( %s )" % (state.name, '+'.join(interfaces), state.state))
    return True


def load_controller(name):
    """Loads the controller whose parameters are at <manager namespace>/<name>."""
    try:
        response = _call('load_controller', LoadController, LoadControllerRequest(name))
    except rospy.ServiceException as error:
        _report_failure('load_controller', error)
        return False
    if response.ok:
        print("Loaded '%s'" % name)
        return True
    print("Error when loading '%s'" % name)
    return False


def unload_controller(name):
    """Unloads a stopped controller."""
    try:
        response = _call('unload_controller', UnloadController, UnloadControllerRequest(name))
    except rospy.ServiceException as error:
        _report_failure('unload_controller', error)
        return False
    if response.ok:
        print("Unloaded '%s' successfully" % name)
        return True
    print("Error when unloading '%s'" % name)
    return False


def start_controller(name):
    return start_stop_controllers(start_controllers=[name])


def start_controllers(names):
    return start_stop_controllers(start_controllers=list(names))


def stop_controller(name):
    return start_stop_controllers(stop_controllers=[name])


def stop_controllers(names):
    return start_stop_controllers(stop_controllers=list(names))


def start_stop_controllers(start_controllers=(), stop_controllers=()):
    """One STRICT switch: all of it happens, or none of it."""
    start_controllers, stop_controllers = list(start_controllers), list(stop_controllers)
    request = SwitchControllerRequest(start_controllers=start_controllers,
                                      stop_controllers=stop_controllers,
                                      strictness=SwitchControllerRequest.STRICT,
                                      start_asap=False, timeout=0.0)
    try:
        response = _call('switch_controller', SwitchController, request)
    except rospy.ServiceException as error:
        _report_failure('switch_controller', error)
        return False
    if response.ok:
        if start_controllers:
            print('Started {} successfully'.format(start_controllers))
        if stop_controllers:
            print('Stopped {} successfully'.format(stop_controllers))
        return True
    print('Error when starting {} and stopping {}'.format(start_controllers, stop_controllers))
    return False


def reload_libraries(force_kill, restore=False):
    """Reloads the controller plugin libraries; with restore, reloads and restarts the controllers
    that were loaded and running before (reloading needs all of them unloaded)."""
    print('Restore: %s' % restore)
    try:
        if restore:
            originally = _controller_states()
        response = _call('reload_controller_libraries', ReloadControllerLibraries,
                         ReloadControllerLibrariesRequest(force_kill))
    except rospy.ServiceException as error:
        _report_failure('reload_controller_libraries', error)
        return False
    if response.ok:
        print('Successfully reloaded libraries')
    else:
        print('Failed to reload libraries. Do you still have controllers loaded?')
    if restore:
        try:
            for state in originally:
                _call('load_controller', LoadController, LoadControllerRequest(state.name))
            running = [state.name for state in originally if state.state == 'running']
            _call('switch_controller', SwitchController,
                  SwitchControllerRequest(start_controllers=running, stop_controllers=[],
                                          strictness=SwitchControllerRequest.BEST_EFFORT,
                                          start_asap=False, timeout=0.0))
        except rospy.ServiceException as error:
            sys.stderr.write('Restoring the controllers that were loaded failed: %s\n' % error)
            return False
        print('Controllers restored to original state')
    return bool(response.ok)
