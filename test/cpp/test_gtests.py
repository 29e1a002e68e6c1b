"""The C++ unit tests (test/cpp/test_*.cpp), one pytest test per gtest case.

CMakeLists.txt builds one gtest executable per source file, named after it, into the devel space
(`make build` runs `catkin_make all tests`); this module finds each one with catkin's own lookup
(the workspace on CMAKE_PREFIX_PATH, as catkin_find does), lists its cases with --gtest_list_tests
and runs them all in one run, as gtest does; a case that failed there, or every case of a run that
crashed, hung or did not report, runs again on its own with --gtest_filter, so a crash belongs to
the case that crashed and a failure shows that case's output. A source without an executable, an
executable that cannot list its cases, a crash or a case that does not report itself all fail:
nothing here is skipped but what gtest itself skips (DISABLED_ cases, GTEST_SKIP).

The sources that cast rays run every case once per instruction set of Embree's kernels that this
CPU runs (TIANRACER_EMBREE_ISA, see include/bullet_plant/ray_kernels.h): Embree runs only the widest
by default, and its narrower kernels take a different path (an AVX-512 machine alone would never
run the 8-wide AVX2 one many users have). The sources that render with OpenGL run every case once
per vector width of Mesa's llvmpipe (LP_NATIVE_VECTOR_WIDTH 128: SSE; 256: AVX2, the widest it
has), for the same reason."""
import glob
import os
import signal
import subprocess
import xml.etree.ElementTree as ET

import pytest
from catkin.find_in_workspaces import find_in_workspaces
from plant_helpers import ISA_VARIABLE, ISAS_RUN, embree_isas
from suite_paths import TEST_DIR

PACKAGE = 'tianracer_description'
SOURCES = sorted(glob.glob(os.path.join(TEST_DIR, 'cpp', 'test_*.cpp')))
CASE_TIMEOUT = 300  # s; a case that hangs fails instead of stalling the suite
RAY_CASTING_SOURCES = {'test_ray_caster', 'test_world_meshes', 'test_gazebo_sonar_sensor'}
GL_SOURCES = {'test_gl_renderer'}
LLVMPIPE_WIDTH = 'LP_NATIVE_VECTOR_WIDTH'


def variants(stem):
    """The (variable, value) pairs each case of a source runs under: the Embree ISAs, the llvmpipe
    widths, or [None] (as it comes)."""
    if stem in RAY_CASTING_SOURCES:
        return [(ISA_VARIABLE, isa) for isa in embree_isas()]
    if stem in GL_SOURCES:
        return [(LLVMPIPE_WIDTH, width) for width in ('128', '256')]
    return [None]


def isa_prefix(variant):
    """How a failing case's command line starts: with the variable it ran under, to run it again."""
    return '%s=%s ' % variant if variant else ''


def gtest_executable(source):
    """The executable catkin_add_gtest built from a source (same stem), or None."""
    name = os.path.splitext(os.path.basename(source))[0]
    found = find_in_workspaces(['libexec'], project=PACKAGE, path=name, first_match_only=True)
    return found[0] if found else None


def parse_test_list(listing):
    """'Suite.Case' names from --gtest_list_tests output (suites flush left and ending in '.', cases
    indented under them; '# GetParam() = ...' comments and gtest_main's banner dropped)."""
    cases, suite = [], None
    for line in listing.splitlines():
        text = line.split('#', 1)[0].rstrip()
        if not text:
            continue
        if not line[0].isspace():
            suite = text if text.endswith('.') else None
        elif suite:
            cases.append(suite + text.strip())
    return cases


class Problem:
    """A test/cpp source whose cases cannot be listed: its one pytest test fails with why."""

    def __init__(self, message):
        self.message = message


def gtest_cases():
    """(stem, variant, executable, case or Problem) for every case of every test/cpp source; variant
    is None but for RAY_CASTING_SOURCES and GL_SOURCES, whose cases come once per variant."""
    params = []
    for source in SOURCES:
        stem = os.path.splitext(os.path.basename(source))[0]
        executable = gtest_executable(source)
        if executable is None:
            params.append(pytest.param(stem, None, None, Problem(
                "no gtest executable '%s' for test/cpp/%s in the devel space of CMAKE_PREFIX_PATH (%s): run "
                "`make build` (catkin_make all tests) and source the workspace" %
                (stem, os.path.basename(source), os.environ.get('CMAKE_PREFIX_PATH', ''))), id=stem))
            continue
        try:
            listing = subprocess.run([executable, '--gtest_list_tests'], capture_output=True, text=True,
                                     timeout=60)
        except subprocess.TimeoutExpired:
            params.append(pytest.param(stem, None, executable, Problem(
                '%s --gtest_list_tests did not finish within 60 s' % executable), id=stem))
            continue
        cases = parse_test_list(listing.stdout) if listing.returncode == 0 else []
        if not cases:
            params.append(pytest.param(stem, None, executable, Problem(
                '%s --gtest_list_tests exited %d and listed no test cases:\n%s%s' %
                (executable, listing.returncode, listing.stdout, listing.stderr)), id=stem))
            continue
        params += [pytest.param(stem, variant, executable, case,
                                id='%s%s:%s' % (stem, '[%s]' % variant[1] if variant else '', case))
                   for variant in variants(stem) for case in cases]
    return params


def gtest_result(report, case):
    """The <testcase> element gtest wrote for 'Suite.Case', or None."""
    suite, name = case.split('.', 1)
    for testcase in ET.parse(report).getroot().iter('testcase'):
        if testcase.get('classname') == suite and testcase.get('name') == name:
            return testcase
    return None


def case_environment(isa, tmp_dir):
    env = dict(os.environ)
    env.pop(ISA_VARIABLE, None)
    env.pop(LLVMPIPE_WIDTH, None)
    env['TMPDIR'] = str(tmp_dir)  # the files a case writes (mesh_fixtures::tempDir) are the test's
    if isa:
        env[isa[0]] = isa[1]
        if isa[0] == ISA_VARIABLE:
            ISAS_RUN.add(isa[1])
    return env


_WHOLE_RUNS = {}  # (executable, variant): {case: <testcase>} of its run with every case, or None


def whole_run(executable, isa, tmp_path_factory):
    """Every case of an executable in one run (a gtest executable's own way; a process a case cost
    0.05 to 0.1 s, some 300 a suite): {case: its <testcase>}, or None where that run crashed, hung
    or did not report (each case then runs on its own, so a crash belongs to the case that crashed)."""
    key = (executable, isa)
    if key not in _WHOLE_RUNS:
        tmp_dir = tmp_path_factory.mktemp(os.path.basename(executable))
        report = tmp_dir / 'gtest.xml'
        try:
            run = subprocess.run([executable, '--gtest_output=xml:%s' % report], capture_output=True, text=True,
                                 timeout=CASE_TIMEOUT, env=case_environment(isa, tmp_dir))
            crashed = run.returncode not in (0, 1) or not report.exists()
        except subprocess.TimeoutExpired:
            crashed = True
        _WHOLE_RUNS[key] = None if crashed else {
            '%s.%s' % (testcase.get('classname'), testcase.get('name')): testcase
            for testcase in ET.parse(report).getroot().iter('testcase')}
    return _WHOLE_RUNS[key]


def failures_of(result):
    return '\n'.join(failure.get('message', '') for failure in result.iter('failure'))


@pytest.mark.parametrize('stem,isa,executable,case', gtest_cases())
def test_gtest_case(stem, isa, executable, case, tmp_path, tmp_path_factory):
    if isinstance(case, Problem):
        pytest.fail(case.message, pytrace=False)
    results = whole_run(executable, isa, tmp_path_factory)
    result = results.get(case) if results is not None else None
    output = ''
    if result is None or result.find('failure') is not None:
        # on its own: a crash is this case's, and a failure shows this case's output alone
        report = tmp_path / 'gtest.xml'
        try:
            run = subprocess.run([executable, '--gtest_filter=' + case, '--gtest_output=xml:%s' % report],
                                 capture_output=True, text=True, timeout=CASE_TIMEOUT,
                                 env=case_environment(isa, tmp_path))
        except subprocess.TimeoutExpired as timeout:
            pytest.fail('%s%s %s did not finish within %d s:\n%s' % (isa_prefix(isa), stem, case, CASE_TIMEOUT,
                                                                       timeout.stdout or ''), pytrace=False)
        output = run.stdout + run.stderr
        alone = gtest_result(report, case) if report.exists() else None
        if run.returncode != 0 or alone is None:
            ended = ('was killed by %s' % signal.Signals(-run.returncode).name if run.returncode < 0
                     else 'exited %d' % run.returncode)
            pytest.fail('%s%s --gtest_filter=%s %s%s:\n%s%s' % (
                isa_prefix(isa), executable, case, ended, '' if alone is not None else ' without reporting the case',
                output, '' if result is None else '\nwith the other cases it failed too: ' + failures_of(result)),
                pytrace=False)
        if result is not None:
            # it passed alone and failed among the others: what another case left behind broke it
            pytest.fail('%s%s %s failed in the run of every case and passed alone: it depends on what another '
                        'case leaves behind:\n%s' % (isa_prefix(isa), executable, case, failures_of(result)),
                        pytrace=False)
        result = alone
    if result.get('result') == 'skipped' or result.get('status') == 'notrun':
        pytest.skip('gtest skipped %s (DISABLED_ or GTEST_SKIP)' % case)
