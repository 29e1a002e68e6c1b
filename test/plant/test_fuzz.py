"""Fuzzing (test/helpers/fuzz_cases.py): mutated URDFs, mutated SDF worlds, random sequences of Python
API calls, and worlds of moving SDF models (nested, included, 1.7 frames, every joint type; mutated,
with hostile values: nan, inf, 1e300, negative sizes, empty names, deep nesting, include loops),
CASES[kind] of each per run from seeds FUZZ_SEED (default 0) on, so a run is reproducible and
`FUZZ_SEED=n make test PYTEST_ARGS='-k fuzz'` tries others. Cases run in subprocesses, BATCH to a
process; a batch that crashes or hangs is rerun case by case, and the test fails naming the seeds.
Every case must end in a run or a DescriptionError, within HANG seconds, with every state it read
back finite. The URDFs and the SDF models then go through the ROS node's spawn services, which must
survive every one and still run a car afterwards."""
import json
import os
import subprocess
import sys

import pytest

from suite_paths import HELPERS

FUZZ_CASES = os.path.join(HELPERS, 'fuzz_cases.py')
CASES = {'urdf': 200, 'sdf': 200, 'api': 200, 'sdf_model': 150}
NODE_SDF_CASES = 60      # of the sdf_model cases, through /gazebo/spawn_sdf_model
BATCH = 50
HANG = 10.0              # s: a case slower than this counts as a hang
STARTUP = 30.0           # s: a subprocess's imports and xacro, on a loaded machine
BASE_SEED = int(os.environ.get('FUZZ_SEED', '0'))


def run_cases(kind, first, count):
    """The rows the cases printed, and what went wrong with the process (None when nothing did)."""
    try:
        result = subprocess.run([sys.executable, FUZZ_CASES, kind, str(first), str(count)], capture_output=True,
                                text=True, timeout=STARTUP + HANG * count)
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or '')
        return [json.loads(line) for line in out.splitlines() if line.startswith('{')], 'hung'
    rows = [json.loads(line) for line in result.stdout.splitlines() if line.startswith('{')]
    if result.returncode != 0:
        return rows, 'exit %d: %s' % (result.returncode, result.stderr.strip().splitlines()[-1:])
    return rows, None


@pytest.mark.parametrize('kind, least_run', [('urdf', 0.2), ('sdf', 0.3), ('api', 1.0), ('sdf_model', 0.3)])
def test_fuzz_cases_never_crash_hang_or_go_non_finite(kind, least_run):
    cases = CASES[kind]
    first = BASE_SEED * cases
    rows, failures = [], []
    for start in range(first, first + cases, BATCH):
        batch, trouble = run_cases(kind, start, BATCH)
        if trouble:
            for seed in range(start, start + BATCH):
                single, trouble = run_cases(kind, seed, 1)
                rows += single
                if trouble:
                    failures.append('%s case %d (python3 test/helpers/fuzz_cases.py %s %d 1): %s' % (kind, seed, kind, seed,
                                                                                            trouble))
        else:
            rows += batch
    assert not failures, failures
    assert sorted(row['seed'] for row in rows) == list(range(first, first + cases))
    assert [row['seed'] for row in rows if row['non_finite']] == [], 'cases that read back a non-finite state'
    assert [row['seed'] for row in rows if row['seconds'] > HANG] == [], 'cases that took over %g s' % HANG
    ran = sum(row['outcome'] == 'ran' for row in rows)
    assert ran >= least_run * cases, 'only %d of %d %s cases got past the parser: the fuzzer is too blunt' % (
        ran, cases, kind)


@pytest.mark.ros
@pytest.mark.slow
def test_the_node_survives_the_fuzzed_urdfs_and_sdf_models(ros, urdf_file):
    from ros_harness import tianracer_plant
    plant = tianracer_plant(ros, urdf_file)
    # The car's robotNamespace is the fuzzed copies' too: it leaves, and comes back at the end.
    assert ros.service('/gazebo/delete_model', '{model_name: tianracer}')['success'] is True
    cases = CASES['urdf']
    spawned = ros.probe('plant/probes/spawn_the_fuzzed_models.py', 'urdf', BASE_SEED * cases,
                        (BASE_SEED + 1) * cases, timeout=600)
    assert spawned >= 0.2 * cases, spawned
    first = BASE_SEED * CASES['sdf_model']
    spawned = ros.probe('plant/probes/spawn_the_fuzzed_models.py', 'sdf_model', first, first + NODE_SDF_CASES,
                        timeout=300)
    assert spawned >= 0.2 * NODE_SDF_CASES, spawned
    assert plant.popen.poll() is None, plant.log()
    respawn = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-urdf', '-param', 'robot_description',
                       '-model', 'tianracer'], timeout=60)
    assert respawn.returncode == 0, respawn.stdout + respawn.stderr + plant.log()
    assert ros.run(['rostopic', 'echo', '-n', '1', '/tianracer/odom'], timeout=30).returncode == 0, plant.log()
