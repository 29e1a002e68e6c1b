"""The simulator node at a very slow pace (real_time_factor 1e-3: a 1 ms step lasts a wall second) keeps
serving services and stops on Ctrl-C. Its own module: it measures wall-clock latencies, so it is
marked serial, and a serial test runs after the other modules (test/conftest.py)."""
import time

import pytest


@pytest.mark.ros
@pytest.mark.serial  # wall-clock latencies, not to be shared with another worker's load
def test_a_slow_pace_keeps_serving_and_stops_on_ctrl_c(ros):
    # At 1e-3 one 1 ms step lasts a wall second; services and Ctrl-C must not wait for it.
    plant = ros.start(['rosrun', 'tianracer_description', 'bullet_plant', '_real_time_factor:=0.001'], 'plant')
    latency = ros.probe('node/probes/a_slow_pace_keeps_serving_and_stops_on_ctrl_c.py')
    assert latency < 0.3, plant.log()
    sent = time.monotonic()
    plant.interrupt()
    assert plant.wait(5) is not None, plant.log()
    assert time.monotonic() - sent < 3
