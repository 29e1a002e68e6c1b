"""Calls the controller manager's ROS services (controller_manager_msgs), as ros_control's module.

The public functions are exactly ros_control 0.20's, with its signatures, printed words and return
values (docs/interfaces.md section 12): list_controller_types, reload_libraries, list_controllers,
load_controller, unload_controller, start_controller, start_controllers, stop_controller,
stop_controllers, start_stop_controllers. Each waits for its service (forever, as upstream does),
calls it and prints what happened; a failed call raises rospy.ServiceException, as upstream's does.
Service names are relative (controller_manager/...), so ROS_NAMESPACE or __ns:= picks the manager.

Nothing else here is public: scripts that also run with upstream's module first on PYTHONPATH may
use only these names (test/compat_packages/test_controller_manager_module.py checks that).
"""
import sys

import rospy
from controller_manager_msgs.srv import (ListControllerTypes, ListControllerTypesRequest,
                                         ListControllers, ListControllersRequest, LoadController,
                                         LoadControllerRequest, ReloadControllerLibraries,
                                         ReloadControllerLibrariesRequest, SwitchController,
                                         SwitchControllerRequest, UnloadController,
                                         UnloadControllerRequest)

# How long a call waits quietly for its service before saying what it is waiting for.
_QUIET_WAIT = 3.0


def _call(service, service_class, request):
    """Waits for the manager's service (forever, as upstream does) and calls it.

    Says on stderr what it waits for when the manager is slow to appear: a silent wait on a wrong
    namespace is the usual way this seems to hang.
    """
    proxy = rospy.ServiceProxy('controller_manager/' + service, service_class)
    try:
        proxy.wait_for_service(_QUIET_WAIT)
    except rospy.ROSException:
        sys.stderr.write('Waiting for service %s: is the controller manager running, and in this '
                         'namespace (set ROS_NAMESPACE or add __ns:=/NAMESPACE)?\n'
                         % proxy.resolved_name)
        proxy.wait_for_service()
    return proxy.call(request)


def _controller_states():
    return _call('list_controllers', ListControllers, ListControllersRequest()).controller


def list_controller_types():
    """Prints the controller types the manager can load, one a line."""
    response = _call('list_controller_types', ListControllerTypes, ListControllerTypesRequest())
    for controller_type in response.types:
        print(controller_type)


def list_controllers():
    """Prints one line per loaded controller: 'name' - 'claimed interfaces' ( state )."""
    states = _controller_states()
    if not states:
        print('No controllers are loaded in mechanism control')
    for state in states:
        # Each interface once, in the order claimed (upstream uses a set: any order).
        interfaces = []
        for claimed in state.claimed_resources:
            if claimed.hardware_interface not in interfaces:
                interfaces.append(claimed.hardware_interface)
        print("'%s' - '%s' ( %s )" % (state.name, '+'.join(interfaces), state.state))


def load_controller(name):
    """Loads the controller whose parameters are at <manager namespace>/<name>; True on success."""
    if _call('load_controller', LoadController, LoadControllerRequest(name)).ok:
        print("Loaded '%s'" % name)
        return True
    print("Error when loading '%s'" % name)
    return False


def unload_controller(name):
    """Unloads a stopped controller; True on success."""
    if _call('unload_controller', UnloadController, UnloadControllerRequest(name)).ok:
        print("Unloaded '%s' successfully" % name)
        return True
    print("Error when unloading '%s'" % name)
    return False


def start_controller(name):
    return start_stop_controllers(start_controllers=[name])


def start_controllers(names):
    return start_stop_controllers(start_controllers=names)


def stop_controller(name):
    return start_stop_controllers(stop_controllers=[name])


def stop_controllers(names):
    return start_stop_controllers(stop_controllers=names)


def start_stop_controllers(start_controllers=(), stop_controllers=()):
    """One STRICT switch: all of it happens, or none of it. True on success."""
    start_controllers, stop_controllers = list(start_controllers), list(stop_controllers)
    request = SwitchControllerRequest(start_controllers=start_controllers,
                                      stop_controllers=stop_controllers,
                                      strictness=SwitchControllerRequest.STRICT,
                                      start_asap=False, timeout=0.0)
    if _call('switch_controller', SwitchController, request).ok:
        if start_controllers:
            print('Started {} successfully'.format(start_controllers))
        if stop_controllers:
            print('Stopped {} successfully'.format(stop_controllers))
        return True
    print('Error when starting {} and stopping {}'.format(start_controllers, stop_controllers))
    return False


def reload_libraries(force_kill, restore=False):
    """Reloads the controller plugin libraries; True on success. With restore, loads again the
    controllers that were loaded before and restarts those that were running (BEST_EFFORT)."""
    print('Restore: %s' % restore)
    if restore:
        originally = _controller_states()
    response = _call('reload_controller_libraries', ReloadControllerLibraries,
                     ReloadControllerLibrariesRequest(force_kill))
    if response.ok:
        print('Successfully reloaded libraries')
    else:
        print('Failed to reload libraries. Do you still have controllers loaded?')
    if restore:
        for state in originally:
            _call('load_controller', LoadController, LoadControllerRequest(state.name))
        running = [state.name for state in originally if state.state == 'running']
        _call('switch_controller', SwitchController,
              SwitchControllerRequest(start_controllers=running, stop_controllers=[],
                                      strictness=SwitchControllerRequest.BEST_EFFORT,
                                      start_asap=False, timeout=0.0))
        print('Controllers restored to original state')
    return bool(response.ok)
