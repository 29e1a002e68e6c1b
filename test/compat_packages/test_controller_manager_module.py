"""The compat controller_manager Python module is interchangeable with ros_control's
(docs/interfaces.md section 12): the same public functions with the same signatures, scripts that
import only those, and the scripts still working when a module offering only those names comes first
on PYTHONPATH (as upstream's does for a user who has it). With an upstream ros_control checkout
(environment variable UPSTREAM_ROS_CONTROL), its own spawner and controller_manager run against the
plant too."""
import ast
import inspect
import os
import re
import subprocess

import pytest
import rospkg

from ros_harness import PYTHON, Process, rosrun_resolved, tianracer_plant
from tianracer_description.tianracer import PACKAGE

COMPAT = rospkg.RosPack().get_path('controller_manager')  # the compat package
SCRIPTS = ('spawner', 'unspawner', 'controller_manager')
MODULE = 'controller_manager.controller_manager_interface'
NS = '/tianracer'
CONTROLLERS = ('joint_state_controller', 'rear_left_velocity_controller', 'rear_right_velocity_controller')


def upstream_signatures():
    """name -> [(parameter, default or None)] from docs/interfaces.md section 12."""
    with open(os.path.join(PACKAGE, 'docs', 'interfaces.md')) as f:
        text = f.read()
    section = text[text.index('## 12.'):]
    signatures = {}
    for name, params in re.findall(r'^    (\w+)\(([^)]*)\)$', section, re.MULTILINE):
        parameters = []
        for param in filter(None, (p.strip() for p in params.split(','))):
            key, _, default = param.partition('=')
            parameters.append((key, ast.literal_eval(default) if default else None))
        signatures[name] = parameters
    return signatures


UPSTREAM = upstream_signatures()


def test_the_documented_list_is_upstreams_ten_functions():
    assert sorted(UPSTREAM) == sorted([
        'list_controller_types', 'reload_libraries', 'list_controllers', 'load_controller', 'unload_controller',
        'start_controller', 'start_controllers', 'stop_controller', 'stop_controllers', 'start_stop_controllers'])


def test_module_offers_exactly_upstreams_public_functions_with_their_signatures():
    import importlib
    module = importlib.import_module(MODULE)
    public = {name: value for name, value in vars(module).items()
              if not name.startswith('_') and callable(value) and getattr(value, '__module__', None) == MODULE}
    assert sorted(public) == sorted(UPSTREAM)
    for name, function in public.items():
        ours = [(p.name, None if p.default is inspect.Parameter.empty
                 else list(p.default) if isinstance(p.default, tuple) else p.default)
                for p in inspect.signature(function).parameters.values()]
        assert ours == UPSTREAM[name], name


def module_names_used(path):
    """The names a script takes from the controller_manager Python package: from-imports, and
    attributes of the module where it is imported as a whole."""
    tree = ast.parse(open(path).read(), path)
    used, module_aliases = [], set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.split('.')[0] == 'controller_manager':
            for alias in node.names:
                if node.module == 'controller_manager' and alias.name == 'controller_manager_interface':
                    module_aliases.add(alias.asname or alias.name)
                else:
                    used.append(alias.name if node.module == MODULE else node.module + '.' + alias.name)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name == MODULE and alias.asname:
                    module_aliases.add(alias.asname)
                elif alias.name.split('.')[0] == 'controller_manager':
                    used.append(alias.name)
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in module_aliases:
            used.append(node.attr)
    return used


@pytest.mark.parametrize('script', SCRIPTS)
def test_scripts_use_only_upstreams_public_names(script):
    used = module_names_used(os.path.join(COMPAT, 'scripts', script))
    assert set(used) <= set(UPSTREAM), 'not in upstream\'s module: %s' % sorted(set(used) - set(UPSTREAM))


def test_the_check_sees_a_helper_upstream_lacks(tmp_path):
    """The AST check itself: the import the issue found (helpers upstream's module lacks) is caught."""
    script = tmp_path / 'spawner'
    script.write_text('from controller_manager.controller_manager_interface import call_with_timeout\n'
                      'from controller_manager import controller_manager_interface as cm\ncm.service_name("x")\n')
    assert sorted(module_names_used(str(script))) == ['call_with_timeout', 'service_name']


# ------------------------------------------------------------------ against the plant (ROS)

def shadow_module(directory):
    """A controller_manager package offering only upstream's public names (ours behind them), to put
    first on PYTHONPATH as a user's upstream install would be."""
    package = directory / 'controller_manager'
    package.mkdir()
    (package / '__init__.py').write_text('')
    ours = os.path.join(COMPAT, 'src', 'controller_manager', 'controller_manager_interface.py')
    (package / 'controller_manager_interface.py').write_text(
        'import importlib.util\n'
        'spec = importlib.util.spec_from_file_location("compat_interface", %r)\n'
        'ours = importlib.util.module_from_spec(spec)\n'
        'spec.loader.exec_module(ours)\n' % ours
        + ''.join('%s = ours.%s\n' % (name, name) for name in sorted(UPSTREAM))
        + 'del importlib, spec, ours\n')
    return str(directory)


def with_pythonpath(env, first):
    return dict(env, PYTHONPATH=first + os.pathsep + env.get('PYTHONPATH', ''))


def run(env, args, timeout=60, namespace=NS):
    return subprocess.run(rosrun_resolved(args, env), env=dict(env, ROS_NAMESPACE=namespace), capture_output=True,
                          text=True, timeout=timeout)


def listed(env, command):
    result = run(env, command + ['list'])
    assert result.returncode == 0, result.stdout + result.stderr
    return {line.split("'")[1]: line.rsplit('(', 1)[1].strip(' )') for line in result.stdout.splitlines()
            if line.startswith("'")}


@pytest.mark.ros
@pytest.mark.slow
def test_scripts_work_with_only_upstreams_names_first_on_pythonpath(ros, urdf_file, tmp_path):
    tianracer_plant(ros, urdf_file)
    env = with_pythonpath(ros.env, shadow_module(tmp_path))
    where = subprocess.run([PYTHON, '-c', 'import %s as m; print(m.__file__)' % MODULE], env=env,
                           capture_output=True, text=True)
    assert where.stdout.strip().startswith(str(tmp_path)), where.stdout + where.stderr

    spawner = Process(['rosrun', 'controller_manager', 'spawner', '__ns:=' + NS, *CONTROLLERS[:2]], env,
                      str(tmp_path / 'spawner.log'))
    ros.processes.append(spawner)
    command = ['rosrun', 'controller_manager', 'controller_manager']
    ros.wait_until(lambda: listed(env, command) == dict.fromkeys(CONTROLLERS[:2], 'running'), 60,
             'the spawner started by the shadowed module: ' + spawner.log())

    spawn = run(env, command + ['spawn', CONTROLLERS[2]])
    assert spawn.stdout == "Loaded '%s'\nStarted ['%s'] successfully\n" % (CONTROLLERS[2], CONTROLLERS[2])
    stop = run(env, command + ['stop', CONTROLLERS[2]])
    assert (stop.returncode, stop.stdout) == (0, "Stopped ['%s'] successfully\n" % CONTROLLERS[2])
    again = run(env, command + ['stop', CONTROLLERS[2]])
    assert (again.returncode, again.stdout) == (1, "Error when starting [] and stopping ['%s']\n" % CONTROLLERS[2])
    types = run(env, command + ['list-types'])
    assert types.returncode == 0 and 'joint_state_controller/JointStateController' in types.stdout.split()

    unspawner = Process(['rosrun', 'controller_manager', 'unspawner', '__ns:=' + NS, CONTROLLERS[1]], env,
                        str(tmp_path / 'unspawner.log'))
    ros.processes.append(unspawner)
    ros.wait_until(lambda: listed(env, command).get(CONTROLLERS[1]) == 'stopped', 60, 'the unspawner: ' + unspawner.log())
    unspawner.interrupt()
    assert unspawner.wait(30) == 0, unspawner.log()
    assert listed(env, command)[CONTROLLERS[1]] == 'running'

    kill = run(env, command + ['kill', CONTROLLERS[2]])
    assert kill.returncode == 0 and "Unloaded '%s' successfully" % CONTROLLERS[2] in kill.stdout
    spawner.interrupt()
    assert spawner.wait(30) == 0, spawner.log()
    assert run(env, command + ['list']).stdout == 'No controllers are loaded in mechanism control\n'


UPSTREAM_CHECKOUT = os.environ.get('UPSTREAM_ROS_CONTROL')


@pytest.mark.ros
@pytest.mark.skipif(not UPSTREAM_CHECKOUT,
                    reason='UPSTREAM_ROS_CONTROL is not set: no ros_control checkout on this machine, so '
                           'upstream\'s own spawner and controller_manager scripts were NOT run against the '
                           'plant (set it to a ros_control source tree to run them)')
def test_upstream_checkout_scripts_against_the_plant(ros, urdf_file, tmp_path):
    package = os.path.join(UPSTREAM_CHECKOUT, 'controller_manager')
    env = with_pythonpath(ros.env, os.path.join(package, 'src'))
    tianracer_plant(ros, urdf_file)
    spawner = Process([PYTHON, os.path.join(package, 'scripts', 'spawner'), '__ns:=' + NS, *CONTROLLERS], env,
                      str(tmp_path / 'upstream_spawner.log'))
    ros.processes.append(spawner)
    command = [PYTHON, os.path.join(package, 'scripts', 'controller_manager')]
    ros.wait_until(lambda: listed(env, command) == dict.fromkeys(CONTROLLERS, 'running'), 60,
             'upstream\'s spawner: ' + spawner.log())
    stop = run(env, command + ['stop', CONTROLLERS[2]])
    assert stop.returncode == 0, stop.stdout + stop.stderr
    assert listed(env, command)[CONTROLLERS[2]] == 'stopped'
    start = run(env, command + ['start', CONTROLLERS[2]])
    assert start.returncode == 0 and listed(env, command)[CONTROLLERS[2]] == 'running'
    spawner.interrupt()
    assert spawner.wait(60) is not None, spawner.log()
    ros.wait_until(lambda: listed(env, command) == {}, 30, 'upstream\'s spawner to unload its controllers on shutdown')
