"""Shared fixtures of every room of test/. The suite runs through `make test`, which builds the catkin workspace and
sources it; run by hand, `source .ws/devel/setup.bash` first. The car's files, controller names
and URDF come from tianracer_description.tianracer, the ROS processes from
test/helpers/ros_harness.py (imported inside the fixtures: without a sourced workspace
pytest_sessionstart says so instead of an import error)."""
import fcntl
import os
import shutil
import sys

import pytest
import yaml

# The rooms (test/<subject>/) import the shared helpers (test/helpers/) by their names.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'helpers'))

# One BLAS thread a process, for the tests and every process they start (inherited). Each rospy
# program imports numpy (genpy does), and OpenBLAS starts a thread a core there: 0.1 s of CPU more
# per import, 0.3 s against 0.19, over the 600 or so ROS tools and probes a run starts; the workers
# already run one to a core.
os.environ.setdefault('OPENBLAS_NUM_THREADS', '1')


def pytest_sessionstart(session):
    if shutil.which('rospack') is None or 'ROS_PACKAGE_PATH' not in os.environ:
        pytest.exit('The ROS workspace is not sourced: run the suite with `make test`, or '
                    '`source .ws/devel/setup.bash` first.', returncode=2)


def pytest_collection_modifyitems(items):
    """The order pytest-xdist hands the modules out in (that of their first test collected), module by
    module, each module's tests in their own order: the modules with slow tests first, so that the run
    does not end waiting for one long module started late; the modules of serial tests last, so that
    they start once the others are handed out. A module holds serial tests only: one in a module of
    others would be handed out early and hold its worker idle until the other workers' tests in
    progress end (a user workspace's build, a minute and a half)."""
    modules = {}
    for item in items:
        module = item.nodeid.split('::')[0]
        serial, slow = modules.get(module, (set(), False))
        serial.add(item.get_closest_marker('serial') is not None)
        modules[module] = (serial, slow or item.get_closest_marker('slow') is not None)
    mixed = sorted(module for module, (serial, _) in modules.items() if len(serial) > 1)
    if mixed:
        raise pytest.UsageError('%s: tests marked serial share a module with tests that are not; move the '
                                'serial ones to a module of their own (docs/tests.md, "serial")' % ', '.join(mixed))
    rank = {module: (True in serial, not slow) for module, (serial, slow) in modules.items()}
    items.sort(key=lambda item: rank[item.nodeid.split('::')[0]])  # stable: each module keeps its order


def _run_lock(config):
    """The file every worker of this run (pytest-xdist's -n) locks around each test, or None in a run
    without workers. The workers' temporary folders are the run's own folder's gw0, gw1 ..."""
    if not hasattr(config, 'workerinput'):
        return None
    if not hasattr(config, '_tianracer_run_lock'):
        path = os.path.join(os.path.dirname(str(config.option.basetemp)), 'serial.lock')
        config._tianracer_run_lock = open(path, 'a')
    return config._tianracer_run_lock


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    """A test marked serial runs alone: it takes the run's lock for itself, the others share it (each
    from its setup to its teardown), so it starts once the other workers' tests in progress end, and
    theirs wait for it."""
    lock = _run_lock(item.config)
    if lock is None:
        yield
        return
    fcntl.flock(lock, fcntl.LOCK_EX if item.get_closest_marker('serial') else fcntl.LOCK_SH)
    try:
        yield
    finally:
        fcntl.flock(lock, fcntl.LOCK_UN)


def pytest_generate_tests(metafunc):
    """A test that takes `embree_isa` runs once per instruction set of Embree's kernels this CPU
    runs (Embree alone would run only the widest)."""
    if 'embree_isa' in metafunc.fixturenames:
        from plant_helpers import embree_isas
        metafunc.parametrize('embree_isa', embree_isas(), indirect=True)


@pytest.fixture
def embree_isa(request, monkeypatch):
    """The ISA this run of the test casts rays with: worlds made in the test, and nodes it starts,
    use it (TIANRACER_EMBREE_ISA in the environment)."""
    from plant_helpers import ISA_VARIABLE, ISAS_RUN
    monkeypatch.setenv(ISA_VARIABLE, request.param)
    ISAS_RUN.add(request.param)
    return request.param


def pytest_terminal_summary(terminalreporter):
    """Which of Embree's kernels the ray-casting tests ran on, and on which CPU."""
    try:
        from plant_helpers import ISAS_RUN, embree_isas
    except ImportError:  # the workspace is not sourced: pytest_sessionstart said so
        return
    if not ISAS_RUN:
        return
    cpu = '?'
    try:
        with open('/proc/cpuinfo') as f:
            cpu = next(line.split(':', 1)[1].strip() for line in f if line.startswith('model name'))
    except (OSError, StopIteration):
        pass
    terminalreporter.write_line('Embree kernels the ray-casting tests ran on: %s (CPU: %s; it runs %s)' % (
        ', '.join(i for i in embree_isas() if i in ISAS_RUN), cpu, ', '.join(embree_isas())))


@pytest.fixture(scope='session')
def urdf_xml():
    from tianracer_description.tianracer import tianracer_urdf
    return tianracer_urdf()


@pytest.fixture(scope='session')
def urdf_file(urdf_xml, tmp_path_factory):
    """The car's URDF in a file, for `rosparam set --textfile` and spawn_model."""
    path = tmp_path_factory.mktemp('model') / 'tianracer.urdf'
    path.write_text(urdf_xml)
    return str(path)


@pytest.fixture(scope='session')
def control_config():
    from tianracer_description.tianracer import CONFIG_YAML
    with open(CONFIG_YAML) as f:
        return yaml.safe_load(f)


@pytest.fixture
def ros(request, tmp_path):
    """A ROS master of the test's own on a free loopback port; its processes stop after the test."""
    if request.node.get_closest_marker('ros') is None:
        pytest.fail("%s starts a ROS master: mark it ros (pytestmark = pytest.mark.ros) so that "
                    "-m 'not ros' leaves it out" % request.node.nodeid, pytrace=False)
    from ros_harness import RosSystem
    system = RosSystem(str(tmp_path))
    yield system
    system.close()
