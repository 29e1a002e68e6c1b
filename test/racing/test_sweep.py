"""Parameter sweeps (tianracer_description.sweep): a scenario's row is the same every time it runs, in
this process or on a Ray worker; a scenario that fails is its row's error (with its seed) and the
others complete; grid and random scenario sets are what they say; the command line runs a random
sweep on a real Ray cluster (`ray start --head` in its own session, started without the ROS workspace
in its environment), streams the rows into a CSV, plots them, and the head stops by its own pid."""
import math
import os
import secrets
import shutil
import signal
import socket
import subprocess
import time

import pytest

from tianracer_description import sweep
from ros_harness import PYTHON, free_port

# A car that crashes within a few hundred steps: soft steering, fast through the turns.
CRASHING = {'seed': 3, 'max_speed': 5.0, 'steering_p': 0.3, 'turn_speed': 1.0, 'steps': 600}
LAPPING = {'seed': 4, 'max_speed': 3.0, 'steps': 900}  # a lap in about 7 s


def both_nan(x, y):
    return isinstance(x, float) and isinstance(y, float) and math.isnan(x) and math.isnan(y)


def same_results(a, b):
    """Rows equal in every column but wall_seconds (NaN equal to NaN: a lap time never reached)."""
    return a.keys() == b.keys() and all(a[k] == b[k] or both_nan(a[k], b[k]) for k in a if k != 'wall_seconds')


def test_a_scenario_run_twice_gives_the_same_row_and_its_fields_reach_the_car():
    for scenario in (CRASHING, LAPPING):
        first, again = sweep.run_scenario(scenario), sweep.run_scenario(dict(scenario))
        assert first['error'] == '' and same_results(first, again), (first, again)
        assert list(first) == list(sweep.SCENARIO_FIELDS + sweep.RESULT_FIELDS)
        assert first['wall_seconds'] > 0
    crash, lap = sweep.run_scenario(CRASHING), sweep.run_scenario(LAPPING)
    assert crash['crashed'] is True and crash['steps_run'] < CRASHING['steps'] and math.isnan(crash['lap_time'])
    assert crash['sim_time'] == pytest.approx(crash['steps_run'] * 0.01)
    assert lap['crashed'] is False and lap['steps_run'] == LAPPING['steps'] and lap['laps'] > 1.0
    assert 5.0 < lap['lap_time'] < lap['sim_time'] == pytest.approx(9.0)
    assert lap['return'] == pytest.approx(lap['laps'] * 21.4243, rel=1e-3), 'metres along the centre line'
    # The defaults are the tutorial's car; each field changes the run.
    assert {k: lap[k] for k in sweep.SCENARIO_FIELDS} == dict(sweep.default_scenario(), **LAPPING)
    for field, value in (('steering_p', 1.0), ('steering_d', 0.2), ('max_speed', 2.5), ('straight_speed', 0.9),
                         ('turn_speed', 0.4)):
        other = sweep.run_scenario(dict(LAPPING, **{field: value}))
        assert other['error'] == '' and other['laps'] != lap['laps'], field


def test_a_failing_scenario_is_its_rows_error_with_its_seed_and_the_others_complete(tmp_path):
    scenarios = [LAPPING, {'track': str(tmp_path / 'no_such.world'), 'seed': 71, 'steps': 50},
                 CRASHING, {'seed': 72, 'colour': 'red'}]
    out = str(tmp_path / 'results.csv')
    rows = sweep.run_sweep(scenarios, out=out, local=True, progress=False)
    assert [row['scenario'] for row in rows] == [0, 1, 2, 3]
    assert rows[0]['error'] == rows[2]['error'] == '' and rows[0]['laps'] > 1.0 and rows[2]['crashed']
    assert rows[1]['error'].startswith('seed 71: FileNotFoundError: track ') and 'no_such.world' in rows[1]['error']
    assert rows[1]['seed'] == 71 and math.isnan(rows[1]['laps'])
    assert rows[3]['error'].startswith('seed 72: ValueError: colour is not a scenario field')
    # The CSV holds the same rows, floats to the last bit.
    assert all(same_results(read, row) for read, row in zip(sweep.read_results(out), rows))
    assert len(sweep.read_results(out)) == 4
    assert 'scenarios  failed  crashes' in sweep.summary(rows)
    assert sweep.summary(rows).splitlines()[1].split()[:3] == ['4', '2', '1']


def test_grid_is_the_product_of_its_axes_and_the_defaults():
    scenarios = sweep.grid(seed=[0, 1, 2], max_speed=[2.0, 3.0], track='RaceTrack')
    assert len(scenarios) == 6
    assert [(s['seed'], s['max_speed']) for s in scenarios] == [(0, 2.0), (0, 3.0), (1, 2.0), (1, 3.0), (2, 2.0),
                                                                (2, 3.0)], 'the first axis varies slowest'
    defaults = sweep.default_scenario()
    assert all(list(s) == list(sweep.SCENARIO_FIELDS) for s in scenarios)
    assert all(s[k] == defaults[k] for s in scenarios for k in sweep.SCENARIO_FIELDS if k not in ('seed', 'max_speed'))
    assert defaults['steering_p'] == 4.0 and defaults['steering_d'] == 1.0, "the tutorial's YAML"
    with pytest.raises(ValueError, match='colour is not a scenario field'):
        sweep.grid(colour=['red'])
    with pytest.raises(ValueError, match='grid axis seed has no values'):
        sweep.grid(seed=[])


def test_random_scenarios_are_drawn_from_their_ranges_and_the_same_seed_draws_the_same():
    ranges = {'seed': (10, 12), 'max_speed': (1.5, 4.0), 'turn_speed': (0.3, 0.3)}
    scenarios = sweep.random_scenarios(200, seed=5, ranges=ranges)
    assert len(scenarios) == 200 and all(list(s) == list(sweep.SCENARIO_FIELDS) for s in scenarios)
    assert {s['seed'] for s in scenarios} == {10, 11, 12} and all(type(s['seed']) is int for s in scenarios)
    speeds = [s['max_speed'] for s in scenarios]
    assert all(1.5 <= v <= 4.0 for v in speeds) and len(set(speeds)) == 200 and max(speeds) - min(speeds) > 2.0
    assert {s['turn_speed'] for s in scenarios} == {0.3}
    defaults = sweep.default_scenario()
    assert all(s[k] == defaults[k] for s in scenarios for k in sweep.SCENARIO_FIELDS if k not in ranges)
    assert sweep.random_scenarios(200, seed=5, ranges=ranges) == scenarios
    assert sweep.random_scenarios(20, seed=5, ranges=ranges) == scenarios[:20], 'drawn scenario by scenario'
    assert sweep.random_scenarios(20, seed=6, ranges=ranges) != scenarios[:20]
    assert all(len({s[k] for s in sweep.random_scenarios(30, seed=1)}) == 30 for k in sweep.RANDOM_RANGES)
    with pytest.raises(ValueError, match='track is not drawn from a range'):
        sweep.random_scenarios(3, seed=1, ranges={'track': ('a', 'b')})
    with pytest.raises(ValueError, match='low <= high'):
        sweep.random_scenarios(3, seed=1, ranges={'max_speed': (3.0, 2.0)})


def test_parquet_without_pyarrow_is_refused_naming_what_to_install(tmp_path):
    try:
        import pyarrow  # noqa: F401
        pytest.skip('pyarrow is installed: .parquet is written')
    except ImportError:
        pass
    result = subprocess.run([PYTHON, '-m', 'tianracer_description.sweep', '--grid', 'seed=0', '--local',
                             '--out', str(tmp_path / 'r.parquet')], capture_output=True, text=True, timeout=60)
    assert result.returncode == 2 and 'needs pyarrow' in result.stderr and 'pip install pyarrow' in result.stderr
    assert not (tmp_path / 'r.parquet').exists()


# A real Ray cluster on this machine.

# The ROS workspace's variables, left out of the head's environment: its workers get them from the
# driver's runtime_env, as on a cluster started in another shell.
WORKSPACE_VARIABLES = ('PYTHONPATH', 'LD_LIBRARY_PATH', 'CMAKE_PREFIX_PATH', 'PKG_CONFIG_PATH')


def session_members(leader):
    """The live processes (not zombies) in the process group or session `leader` started."""
    members = []
    for entry in os.listdir('/proc'):
        if not entry.isdigit():
            continue
        try:
            with open('/proc/%s/stat' % entry) as f:
                fields = f.read().rsplit(')', 1)[1].split()  # after "pid (comm)": state ppid pgrp session
        except OSError:
            continue  # gone meanwhile
        if fields[0] != 'Z' and leader in (int(fields[2]), int(fields[3])):
            members.append(int(entry))
    return members


class RayHead:
    """`ray start --head --block` on a loopback port in a session of its own, with a token of its own;
    stopped by SIGTERM to its own pid (it drains and stops its processes), its group killed only if
    something outlives that."""

    def __init__(self, temp_dir, log_path, cpus=2):
        ray = shutil.which('ray')
        assert ray, "ray's command line is not on PATH: tools/setup.sh installs ray"
        self.port = free_port()
        self.address = '127.0.0.1:%d' % self.port
        token = secrets.token_hex(32)
        self.client_env = dict(os.environ, RAY_AUTH_MODE='token', RAY_AUTH_TOKEN=token)
        env = {k: v for k, v in self.client_env.items()
               if k not in WORKSPACE_VARIABLES and not k.startswith('ROS_')}
        env[sweep.CLUSTER_VARIABLE] = '0'  # the head on loopback only
        self.log_path = log_path
        self._log = open(log_path, 'w')
        self.popen = subprocess.Popen(
            [ray, 'start', '--head', '--block', '--port=%d' % self.port, '--num-cpus=%d' % cpus,
             '--include-dashboard=false', '--disable-usage-stats', '--temp-dir=%s' % temp_dir],
            env=env, stdout=self._log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)

    def wait_until_listening(self, timeout=60):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            assert self.popen.poll() is None, 'ray start exited (%s): %s' % (self.popen.returncode, self.log())
            with socket.socket() as s:
                if s.connect_ex(('127.0.0.1', self.port)) == 0:
                    return
            time.sleep(0.2)
        raise AssertionError('the Ray head did not listen on %s within %g s: %s' % (self.address, timeout, self.log()))

    def stop(self, timeout=30):
        """SIGTERM to the head's pid; True when it and every process of its session are gone in time."""
        if self.popen.poll() is None:
            os.kill(self.popen.pid, signal.SIGTERM)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.popen.poll() is not None and not session_members(self.popen.pid):
                return True
            time.sleep(0.1)
        return False

    def kill(self):
        """The fallback: SIGKILL to the whole process group."""
        try:
            os.killpg(self.popen.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self.popen.wait(10)

    def close_log(self):
        self._log.close()

    def log(self):
        self._log.flush()
        with open(self.log_path, errors='replace') as f:
            return f.read()[-3000:]


@pytest.fixture
def ray_head(tmp_path, tmp_path_factory):
    # Ray's sockets live under its temp dir and a unix socket's path is at most 107 bytes: a short
    # folder of this session's temp dir, not the test's own (long) tmp_path.
    head = RayHead(str(tmp_path_factory.mktemp('ray')), str(tmp_path / 'ray_head.log'))
    try:
        head.wait_until_listening()
        yield head
    finally:
        if not head.stop():
            head.kill()
        head.close_log()


@pytest.mark.slow
def test_the_command_line_sweeps_on_a_ray_cluster_by_address_and_its_rows_are_the_local_ones(ray_head, tmp_path):
    out, png = tmp_path / 'results.csv', tmp_path / 'summary.png'
    env = dict(ray_head.client_env)
    env.pop(sweep.CLUSTER_VARIABLE, None)  # the sweep sets it for a loopback address
    started = time.monotonic()
    result = subprocess.run(
        [PYTHON, '-m', 'tianracer_description.sweep', '--address', ray_head.address, '--random', '20', '--seed', '27',
         '--range', 'max_speed=2,7', '--range', 'turn_speed=0.4,1', '--range', 'steering_p=0.3,6',
         '--steps', '300', '--out', str(out), '--plot', str(png)],
        env=env, capture_output=True, text=True, timeout=180)
    took = time.monotonic() - started
    assert result.returncode == 0, result.stdout + result.stderr + ray_head.log()
    rows = sweep.read_results(str(out))
    assert len(rows) == 20 and sorted(row['scenario'] for row in rows) == list(range(20))
    assert [row['error'] for row in rows] == [''] * 20
    assert all(row['steps'] == 300 and 0 < row['steps_run'] <= 300 for row in rows)
    crashes = sum(row['crashed'] for row in rows)
    assert 0 < crashes < 20, 'these draws crash some cars and not others: %d crashed' % crashes
    assert png.read_bytes()[:8] == b'\x89PNG\r\n\x1a\n' and png.stat().st_size > 10000
    assert result.stdout.splitlines()[1].split()[:3] == ['20', '0', str(crashes)], result.stdout
    assert '100%' in result.stderr, 'the progress bar'
    # The rows are those of the scenarios the command line draws, and in this process the same
    # scenarios give the same rows (a crash and a car still going).
    drawn = sweep.random_scenarios(20, 27, dict(sweep.RANDOM_RANGES, max_speed=(2, 7), turn_speed=(0.4, 1),
                                                steering_p=(0.3, 6)))
    by_index = {row['scenario']: row for row in rows}
    assert [sweep.scenario_of(by_index[i]) for i in range(20)] == [dict(s, steps=300) for s in drawn]
    for crashed in (True, False):
        row = next(row for row in rows if row['crashed'] == crashed)
        local = dict({'scenario': row['scenario']}, **sweep.run_scenario(sweep.scenario_of(row)))
        assert same_results(local, row), (local, row)
    print('the sweep on Ray: %.1f s' % took)
    # The head stops by its own pid, and everything it started with it.
    pid = ray_head.popen.pid
    assert session_members(pid), 'the head runs'
    assert ray_head.stop(), 'still running after SIGTERM to the head: %s' % session_members(pid)
