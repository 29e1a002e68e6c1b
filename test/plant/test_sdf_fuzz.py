"""Fuzzing the SDF model reader (src/plant/description/sdf_model.cpp): worlds of models that move
(nested, included, 1.7 frames, every joint type), mutated as test_fuzz.py mutates URDFs, with hostile
values (nan, inf, 1e300, negative sizes, empty names), deep nesting and include loops
(test/helpers/fuzz_cases.py, kind sdf_model). Each case runs in a subprocess, BATCH to a process, so a
crash fails this test naming the seed instead of killing pytest; every case must load or raise
DescriptionError, within HANG seconds, with every state it read back finite."""
import json
import os
import subprocess
import sys

from suite_paths import HELPERS

FUZZ_CASES = os.path.join(HELPERS, 'fuzz_cases.py')
CASES = 150
BATCH = 50
HANG = 10.0     # s a case
STARTUP = 30.0  # s: a subprocess's imports on a loaded machine
BASE_SEED = int(os.environ.get('FUZZ_SEED', '0'))


def run_cases(first, count):
    """The rows the cases printed, and what went wrong with the process (None when nothing did)."""
    try:
        result = subprocess.run([sys.executable, FUZZ_CASES, 'sdf_model', str(first), str(count)], capture_output=True,
                                text=True, timeout=STARTUP + HANG * count)
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or '')
        return [json.loads(line) for line in out.splitlines() if line.startswith('{')], 'hung'
    rows = [json.loads(line) for line in result.stdout.splitlines() if line.startswith('{')]
    if result.returncode != 0:
        return rows, 'exit %d: %s' % (result.returncode, result.stderr.strip().splitlines()[-1:])
    return rows, None


def test_fuzzed_sdf_models_never_crash_hang_or_go_non_finite():
    first = BASE_SEED * CASES
    rows, failures = [], []
    for start in range(first, first + CASES, BATCH):
        batch, trouble = run_cases(start, BATCH)
        if trouble:
            for seed in range(start, start + BATCH):
                single, trouble = run_cases(seed, 1)
                rows += single
                if trouble:
                    failures.append('case %d (python3 test/helpers/fuzz_cases.py sdf_model %d 1): %s' % (seed, seed,
                                                                                                        trouble))
        else:
            rows += batch
    assert not failures, failures
    assert sorted(row['seed'] for row in rows) == list(range(first, first + CASES))
    assert [row['seed'] for row in rows if row['non_finite']] == [], 'cases that read back a non-finite state'
    assert [row['seed'] for row in rows if row['seconds'] > HANG] == [], 'cases that took over %g s' % HANG
    ran = sum(row['outcome'] == 'ran' for row in rows)
    assert ran >= 0.3 * CASES, 'only %d of %d cases got past the parser: the fuzzer is too blunt' % (ran, CASES)
