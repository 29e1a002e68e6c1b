"""The Python module's guards against misuse: step() takes a non-negative int and can be interrupted."""
import os
import signal
import subprocess
import sys
import time

import pytest

from tianracer_description import bullet_plant


def test_step_refuses_a_bool_and_a_negative_count():
    world = bullet_plant.World()
    with pytest.raises(TypeError, match='int'):
        world.step(True)
    with pytest.raises(TypeError, match='int'):
        world.step(1.0)
    with pytest.raises(ValueError, match='negative'):
        world.step(-1)
    assert world.steps == 0
    world.step(3)
    assert world.steps == 3


def test_a_long_step_stops_on_ctrl_c():
    script = ('from tianracer_description import bullet_plant\n'
              'import sys\n'
              'world = bullet_plant.World()\n'
              'print("stepping", flush=True)\n'
              'world.step(2**31 - 1)\n')
    proc = subprocess.Popen([sys.executable, '-c', script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=dict(os.environ), text=True)
    try:
        assert proc.stdout.readline().strip() == 'stepping'
        time.sleep(1.0)
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=10)
        assert time.monotonic() - sent < 5
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode != 0
    assert 'KeyboardInterrupt' in err


def test_a_step_below_a_nanosecond_is_refused():
    from plant_helpers import sdf_world
    with pytest.raises(bullet_plant.DescriptionError, match=r'max_step_size> 1e-10 is out of range'):
        bullet_plant.World.from_sdf(sdf_world(step=1e-10))
    assert bullet_plant.World.from_sdf(sdf_world(step=1e-9)).time_step == pytest.approx(1e-9)
