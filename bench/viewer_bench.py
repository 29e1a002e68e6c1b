"""What the browser viewer costs (`make bench-viewer`): the plant's CPU with a page open, and the
page's frame rate in headless chromium.

The car (the tutorial's URDF, its sensors on) on the mesh race track of bench/sensor_bench.py (the
race track's walls as one OBJ, a textured OBJ floor), the plant at real time, the viewer serving it.
Per round, each with its own ROS master, side by side: the plant's user + system CPU over WINDOW s of
wall time with one page open in Debian's chromium (headless, WebGL on SwiftShader, 960 x 720)
against the mean of a window before the page opened and one after it closed, as a share of one core; the page's frames drawn a second over the same
window, and the viewer process's own CPU. Medians of ROUNDS rounds.
Targets (issue 26): the plant grows by at most 3 % of a core with one page open at real time; the
page draws at 30 frames a second or more. The page draws a frame per change (poses at the plant's
~scene_rate, 30 a simulated second): at real time it draws about 30 a second where it keeps up.
"""
import os
import statistics
import sys
import tempfile
import time

TEST_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test')
sys.path[:0] = [os.path.join(TEST_DIR, 'helpers'), os.path.join(TEST_DIR, 'viewer')]  # the suite's helpers, its viewer room
from ros_plant_bench import cpu_seconds, plant_pid  # noqa: E402
from sensor_bench import cpu_name, write_mesh_track  # noqa: E402
from test_viewer import browser, wait_for  # noqa: E402  (the test's chromium, as a user opens it)
from ros_harness import RosSystem, free_port, tianracer_plant  # noqa: E402
from tianracer_description.tianracer import tianracer_urdf  # noqa: E402

ROUNDS = 3
WINDOW = 20.0  # s


def one_round(workdir):
    world, _ = write_mesh_track(workdir)
    urdf = os.path.join(workdir, 'tianracer.urdf')
    with open(urdf, 'w') as f:
        f.write(tianracer_urdf())
    ros = RosSystem(workdir)
    driver = None
    try:
        plant = tianracer_plant(ros, urdf, world=world)
        port = free_port()
        viewer = ros.start(['rosrun', 'tianracer_description', 'viewer', '_port:=%d' % port], 'viewer')
        url = 'http://127.0.0.1:%d/' % port
        ros.wait_until(lambda: ('viewer: open ' + url) in viewer.log(), 30, 'the viewer to serve')
        pid, viewer_pid = plant_pid(plant.pid), viewer.pid
        time.sleep(3.0)

        def window(measure_page=False):
            plant_cpu, viewer_cpu, wall = cpu_seconds(pid), cpu_seconds(viewer_pid), time.monotonic()
            frames = driver.execute_script('return viewer.framesDrawn()') if measure_page else 0
            time.sleep(WINDOW)
            elapsed = time.monotonic() - wall
            fps = (driver.execute_script('return viewer.framesDrawn()') - frames) / elapsed if measure_page else 0
            return ((cpu_seconds(pid) - plant_cpu) / elapsed, (cpu_seconds(viewer_pid) - viewer_cpu) / elapsed, fps)

        before = window()
        driver = browser()
        driver.get(url)
        wait_for(driver, '!!(window.viewer && viewer.ready())', 60, 'the scene to be drawn')
        time.sleep(2.0)
        with_page = window(measure_page=True)
        driver.quit()
        driver = None
        time.sleep(2.0)
        after = window()
        return {'alone': (before[0] + after[0]) / 2, 'with_page': with_page[0], 'viewer': with_page[1],
                'fps': with_page[2]}
    finally:
        if driver:
            driver.quit()
        ros.close()


def main():
    print('CPU: %s, %d cores; %d rounds of %g s with no page and with one' % (cpu_name(), os.cpu_count(), ROUNDS,
                                                                             WINDOW), flush=True)
    rounds = []
    for r in range(ROUNDS):
        with tempfile.TemporaryDirectory() as workdir:
            rounds.append(one_round(workdir))
        x = rounds[-1]
        print('round %d: plant %.1f %% of a core alone, %.1f %% with a page (%+.1f %%); viewer %.1f %%; page %.0f fps'
              % (r + 1, 100 * x['alone'], 100 * x['with_page'], 100 * (x['with_page'] - x['alone']), 100 * x['viewer'],
                 x['fps']), flush=True)

    def median(f):
        return statistics.median(f(x) for x in rounds)
    print('\nmedians over %d rounds: the plant %+.1f %% of a core with one page open (target: at most +3 %%); '
          'the viewer process %.1f %%; the page %.0f frames a second in headless chromium (target: 30 or more)'
          % (ROUNDS, 100 * median(lambda x: x['with_page'] - x['alone']), 100 * median(lambda x: x['viewer']),
             median(lambda x: x['fps'])))


if __name__ == '__main__':
    main()
