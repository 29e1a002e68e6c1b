"""Running a sweep: in this process, or as Ray tasks on a cluster (or a local Ray of its own),
its rows written as the scenarios finish (see the package's docstring for Ray's environment, loopback
heads and token authentication)."""
import itertools
import logging
import os
import socket
import sys

from tianracer_description.sweep.results import INDEX_FIELD, ResultsFile
from tianracer_description.sweep.scenarios import failed_row, run_scenario


CLUSTER_VARIABLE = 'RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER'  # 0: Ray's node address is loopback
# What Ray's workers need of the driver's environment to import the package and find the ROS packages
# (rospack for xacro and the car's files), besides every ROS_* and TIANRACER_* variable.
WORKER_VARIABLES = ('PYTHONPATH', 'LD_LIBRARY_PATH', 'CMAKE_PREFIX_PATH', 'PKG_CONFIG_PATH')
LOOPBACK_HOSTS = ('localhost', '::1')


def local_results(scenarios):
    """(index, row) of each scenario, run one after another in this process."""
    for index, scenario in enumerate(scenarios):
        yield index, run_scenario(scenario)


def worker_environment():
    """The driver's variables Ray's workers need to import the package and find the ROS packages."""
    return {name: value for name, value in os.environ.items()
            if name in WORKER_VARIABLES or name.startswith(('ROS_', 'TIANRACER_'))}


def host_and_port(address):
    """(host, port) of 'host:port' (or 'ray://host:port'); None for another form ('auto')."""
    host, sep, port = address.split('://', 1)[-1].rpartition(':')
    return (host.strip('[]'), int(port)) if sep and host and port.isdigit() else None


def is_loopback(address):
    where = host_and_port(address)
    return where is not None and (where[0] in LOOPBACK_HOSTS or where[0].startswith('127.'))


def check_listening(address, timeout=5.0):
    """ConnectionError unless something accepts a connection at the address: ray.init retries a
    dead address for a quarter of an hour before it gives up."""
    where = host_and_port(address)
    if where is None:
        return
    try:
        socket.create_connection(where, timeout).close()
    except OSError as error:
        raise ConnectionError('nothing answers at %s (%s): start the cluster\'s head there (ray start --head '
                              '--port=%d) or give --address of one that runs' % (address, error, where[1])) from None


def connect_ray(address=None):
    """ray, initialised: connected to the cluster at `address`, or (None) a local Ray of its own, the
    job's workers given worker_environment(). Sets RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER=0 (unless it is
    set) for a loopback address before ray is imported: a head on loopback is found only so."""
    if address is not None:
        check_listening(address)
        if is_loopback(address):
            os.environ.setdefault(CLUSTER_VARIABLE, '0')
    import ray
    settings = dict(log_to_driver=False, logging_level=logging.WARNING,
                    runtime_env={'env_vars': worker_environment()})
    if address is None:
        ray.init(include_dashboard=False, **settings)
        return ray
    try:
        ray.init(address=address, **settings)
    except ConnectionError as error:
        # What is listening did not take us: most often token authentication, which `ray start` turns
        # on when it finds ~/.ray/auth_token, and which a driver given an address never assumes.
        raise ConnectionError(
            'cannot join the Ray cluster at %s (%s). A head with token authentication takes drivers with '
            'RAY_AUTH_MODE=token and its token (~/.ray/auth_token or RAY_AUTH_TOKEN) in their environment.'
            % (address, error)) from None
    return ray


def ray_results(ray, scenarios, workers=None):
    """(index, row) of each scenario as it finishes, run as Ray tasks (one CPU each) through `ray`
    (connect_ray's), at most `workers` at a time (default: the cluster's CPUs). A task that fails in
    Ray (a worker that dies, cannot import the package) is its scenario's error row; the others go on."""
    remote_scenario = ray.remote(num_cpus=1)(run_scenario)
    limit = workers or max(1, int(ray.cluster_resources().get('CPU', 1)))
    waiting = iter(enumerate(scenarios))
    running = {}

    def submit():
        for index, scenario in itertools.islice(waiting, 1):
            running[remote_scenario.remote(scenario)] = (index, scenario)

    for _ in range(limit):
        submit()
    while running:
        done, _ = ray.wait(list(running), num_returns=1)
        for ref in done:
            index, scenario = running.pop(ref)
            try:
                row = ray.get(ref)
            except Exception as error:  # noqa: BLE001  Ray's failure of one task: its row's
                row = failed_row(scenario, error)
                row['error'] = 'on Ray: ' + row['error']
            submit()
            yield index, row


def run_sweep(scenarios, out=None, address=None, local=False, workers=None, progress=True):
    """Runs the scenarios (in this process with local, else on Ray: the cluster at `address`, or a local
    Ray of its own) and returns their rows in the scenarios' order, each with its INDEX_FIELD; with
    `out`, writes them there as they finish. A progress bar on stderr unless progress is False."""
    from tqdm import tqdm
    ray = None if local else connect_ray(address)  # before the results file: no empty file when it fails
    results = None
    try:
        results = ResultsFile(out) if out else None
        rows = [None] * len(scenarios)
        finished = local_results(scenarios) if local else ray_results(ray, scenarios, workers)
        with tqdm(total=len(scenarios), file=sys.stderr, unit='scenario', disable=not progress) as bar:
            for index, row in finished:
                row = dict({INDEX_FIELD: index}, **row)
                rows[index] = row
                if results:
                    results.write(row)
                bar.update(1)
    finally:
        if ray:
            ray.shutdown()
        if results:
            results.close()
    return rows
