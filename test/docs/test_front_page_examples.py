"""The front pages' examples run as printed: each indented block of README.md and README.zh-CN.md
that holds a Python session (`>>>` lines) is run, its shell lines with bash and its session with
/usr/bin/python3 from the repository's root, as a newcomer would paste them. A line that raises
fails the test with the block's text. No ROS master is needed (the plant from Python, Gymnasium)."""
import os
import re
import subprocess

import pytest

from suite_paths import REPOSITORY


def sessions(page):
    """(shell lines, Python source) of each indented block of `page` that holds `>>>` lines."""
    with open(os.path.join(REPOSITORY, page), encoding='utf-8') as f:
        text = f.read()
    found = []
    for block in re.findall(r'(?:^(?: {4}| {7}).*\n)+', text, re.MULTILINE):
        lines = [line.strip() for line in block.splitlines()]
        if not any(line.startswith('>>> ') for line in lines):
            continue
        shell = [line for line in lines if line and not line.startswith(('>>>', '...'))
                 and line != '/usr/bin/python3']
        python = [line[4:] for line in lines if line.startswith(('>>> ', '... '))]
        found.append((shell, '\n'.join(python) + '\n'))
    return found


@pytest.mark.parametrize('page', ['README.md', 'README.zh-CN.md'])
def test_the_front_pages_python_sessions_run_as_printed(page, tmp_path):
    blocks = sessions(page)
    assert len(blocks) == 2, '%s: the plant from Python and racing, each a session' % page
    for shell, python in blocks:
        for line in shell:
            if line.startswith('source '):
                continue  # the suite runs with the workspace sourced already
            # The examples write to /tmp; the test to a folder of its own.
            subprocess.run(line.replace('/tmp/', str(tmp_path) + '/'), shell=True, executable='/bin/bash',
                           cwd=REPOSITORY, check=True, timeout=120)
        run = subprocess.run(['/usr/bin/python3', '-c', python.replace('/tmp/', str(tmp_path) + '/')],
                             cwd=REPOSITORY, capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, '%s\n%s' % (python, run.stderr[-3000:])


def test_a_session_that_raises_fails(tmp_path):
    """The check can fail: a session whose line raises is reported by its exit status."""
    page = tmp_path / 'page.md'
    page.write_text('Intro\n\n    /usr/bin/python3\n    >>> import os\n    >>> os.stat("/no/such/file")\n')
    [(shell, python)] = sessions(str(page))  # an absolute path: os.path.join keeps it
    assert shell == [] and 'os.stat' in python
    run = subprocess.run(['/usr/bin/python3', '-c', python], capture_output=True, text=True)
    assert run.returncode != 0 and 'FileNotFoundError' in run.stderr
