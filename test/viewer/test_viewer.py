"""The browser viewer (scripts/viewer, tianracer_description.viewer, web/): Debian's chromium, headless,
driven by selenium through chromedriver, opens the page the node serves against the plant with the
race track and the car, as a user opens it over SSH. What it draws is checked in the screenshot,
against the world file's layout; the car's drawn pose against /gazebo/model_states as it drives.
"""
import contextlib
import io
import math
import os
import re
import time
import xml.etree.ElementTree as ET

import matplotlib.image
import numpy as np
import pytest

pytestmark = pytest.mark.ros

CHROMIUM = '/usr/bin/chromium'
CHROMEDRIVER = '/usr/bin/chromedriver'
WINDOW = (960, 720)


def track_walls(world_file):
    """(centre x y z, size x y z, yaw, colour r g b) of each box wall of the world file."""
    walls = []
    for model in ET.parse(world_file).getroot().iter('model'):
        size = model.findtext('link/visual/geometry/box/size')
        if size:
            x, y, z, _, _, yaw = map(float, model.findtext('pose').split())
            colour = tuple(map(float, model.findtext('link/visual/material/diffuse').split()[:3]))
            walls.append(((x, y, z), tuple(map(float, size.split())), yaw, colour))
    return walls


def distance_to_box(point, wall):
    """The horizontal distance from (x, y) to a wall's footprint (0 inside)."""
    (cx, cy, _), (sx, sy, _), yaw, _ = wall
    dx, dy = point[0] - cx, point[1] - cy
    u = math.cos(yaw) * dx + math.sin(yaw) * dy
    v = -math.sin(yaw) * dx + math.cos(yaw) * dy
    return math.hypot(max(abs(u) - sx / 2, 0.0), max(abs(v) - sy / 2, 0.0))


def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ('--headless=new', '--no-sandbox', '--disable-dev-shm-usage',
                     '--window-size=%d,%d' % WINDOW,
                     # WebGL on the CPU where there is no GPU (SwiftShader, chromium's own)
                     '--use-angle=swiftshader', '--enable-unsafe-swiftshader'):
        options.add_argument(argument)
    from selenium.common.exceptions import WebDriverException
    from urllib3.exceptions import MaxRetryError
    try:
        return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    except (WebDriverException, MaxRetryError):
        # Once in CI (stop 50) chromedriver answered on its port and then refused the session it was
        # started for ("Connection refused" on POST /session); selenium stops it: a new one, once.
        return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


def wait_for(driver, script, timeout, what, state=None):
    """Until `script` is true in the page; at the timeout an AssertionError with the browser's log and
    the page's `state` script's answer (what the wait was for, part by part)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if driver.execute_script('return ' + script):
            return
        time.sleep(0.1)
    raise AssertionError('timed out after %g s waiting for %s%s; the browser said: %s'
                         % (timeout, what, '' if state is None else ' (%s)' % driver.execute_script('return ' + state),
                            driver.get_log('browser')))


def at_rest(read_xy, timeout=20.0, still=0.02):
    """(x, y) once two readings of read_xy() 1 s of wall time apart lie within `still` m: a car that
    stops stops then whatever the real time factor (AssertionError with its readings at the timeout)."""
    deadline = time.monotonic() + timeout
    readings = [read_xy()]
    while time.monotonic() < deadline:
        time.sleep(1.0)
        readings.append(read_xy())
        if math.hypot(readings[-1][0] - readings[-2][0], readings[-1][1] - readings[-2][1]) < still:
            return readings[-1]
    raise AssertionError('still moving after %g s: %s' % (timeout, readings))


@pytest.fixture(scope='module')
def chromium():
    """One chromium for the module's pages, as a user keeps one browser open: each test opens its own
    viewer's page in it. A browser started for each test cost its GPU process the compiling of the
    page's shaders again (SwiftShader, on the CPU), most of what a short test spent."""
    driver = browser()
    yield driver
    driver.quit()


@contextlib.contextmanager
def opened(ros, driver, world, urdf_file=None):
    """The plant on `world` (with the car and the tutorial's YAML when `urdf_file`), the viewer on a
    free port, and the page on it in `driver` with the scene drawn: (plant, viewer process, url).
    The browser leaves the page (about:blank) when the test ends, before its viewer stops."""
    from ros_harness import start_plant, tianracer_plant
    plant = tianracer_plant(ros, urdf_file, world=world) if urdf_file else start_plant(ros, world)
    # port 0: the viewer binds a port the system picks and prints it. A port found free here first
    # could be taken before the viewer bound it: chromium, starting beside it, took one in CI.
    # ~rate 10: the page gets the poses ten times a second, not the default 30, and draws a third as
    # often: SwiftShader draws each frame on the CPU (chromium's CPU over the module 108 -> 77 s)
    viewer = ros.start(['rosrun', 'tianracer_description', 'viewer', '_port:=0', '_rate:=10'], 'viewer')
    opened_at = re.compile(r'viewer: open (http://127\.0\.0\.1:\d+/)')
    ros.wait_until(lambda: opened_at.search(viewer.log()), 30, 'the viewer to serve')
    url = opened_at.search(viewer.log()).group(1)
    try:
        driver.get(url)
        wait_for(driver, '!!(window.viewer && viewer.ready())', 30, 'the scene to be drawn',
                 state='window.viewer ? viewer.readiness() : "no viewer in the page"')
        yield plant, viewer, url
    finally:
        driver.get('about:blank')


@pytest.fixture
def page(ros, chromium, urdf_file):
    """The race track and the car, in a page: (ros, viewer process, driver, url)."""
    from tianracer_description.tianracer import RACE_TRACK_WORLD
    with opened(ros, chromium, RACE_TRACK_WORLD, urdf_file) as (_, viewer, url):
        yield ros, viewer, chromium, url


def look_from_above(driver, lo, hi):
    """The view straight down (a hair off: z is up for the orbit controls) on the box lo-hi (x, y);
    the eye's position."""
    centre = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)
    eye = [centre[0], centre[1] - 0.01, 1.2 * max(hi[0] - lo[0], hi[1] - lo[1])]
    driver.execute_script('viewer.lookAt(arguments[0], arguments[1])', eye, [centre[0], centre[1], 0])
    return np.array(eye)


def pixels_at(driver, image, points):
    """The 3 x 3 pixels of `image` about where each (x, y, z) of `points` is drawn; None off the
    window or under the panel."""
    panel = driver.execute_script("const r = document.getElementById('panel').getBoundingClientRect();"
                                  "return [r.left, r.top, r.right, r.bottom];")
    drawn = driver.execute_script('return arguments[0].map((p) => viewer.project(p[0], p[1], p[2]))',
                                  [list(map(float, p)) for p in points])
    out = []
    for px, py in drawn:
        px, py = int(round(px)), int(round(py))
        inside = 1 <= px < image.shape[1] - 1 and 1 <= py < image.shape[0] - 1
        under_panel = panel[0] - 2 <= px <= panel[2] + 2 and panel[1] - 2 <= py <= panel[3] + 2
        out.append(image[py - 1:py + 2, px - 1:px + 2].reshape(9, 3) if inside and not under_panel else None)
    return out


def tick_overlay(driver, topic, what):
    """Ticks `topic` in the page's sensor list once the viewer offers it, and waits for two of its
    messages drawn; the checkbox's selector."""
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.common.by import By
    box = '#overlay_topics input[data-topic="%s"]' % topic
    wait_for(driver, "!!document.querySelector('%s')" % box, 30, what + ' to be offered')
    for _ in range(10):
        try:  # the page makes the list again when another sensor's topic comes: click the one shown now
            driver.find_element(By.CSS_SELECTOR, box).click()
            break
        except StaleElementReferenceException:
            time.sleep(0.1)
    wait_for(driver, "viewer.overlayFrames('%s') >= 2" % topic, 30, what + ' drawn in the page')
    return box


def screenshot(driver):
    """The window as the user sees it, r g b in 0-255."""
    return np.round(255 * matplotlib.image.imread(io.BytesIO(driver.get_screenshot_as_png()))[:, :, :3])


@pytest.mark.slow
def test_the_screenshot_shows_the_race_tracks_walls_where_the_world_has_them(page):
    from tianracer_description.tianracer import RACE_TRACK_WORLD
    _, _, driver, _ = page
    walls = track_walls(RACE_TRACK_WORLD)
    xs = [w[0][0] for w in walls]
    ys = [w[0][1] for w in walls]
    look_from_above(driver, (min(xs), min(ys)), (max(xs), max(ys)))
    image = screenshot(driver)

    # Each wall's top (5 cm wide: a few pixels, their edges blended with the floor) is drawn in its
    # red, lit from above.
    tops = [(cx, cy, cz + size[2] / 2) for (cx, cy, cz), size, _, _ in walls]
    seen = 0
    for wall, pixels in zip(walls, pixels_at(driver, image, tops)):
        if pixels is None:
            continue
        seen += 1
        reddest = pixels[np.argmax(pixels[:, 0] - pixels[:, 1:].max(axis=1))]
        assert reddest[0] > reddest[1] + 80 and reddest[0] > reddest[2] + 80, (
            'the wall at (%.2f, %.2f), colour %s, is drawn %s' % (wall[0][0], wall[0][1], wall[3], pixels))
    assert seen >= 0.9 * len(walls), 'only %d of %d walls in view' % (seen, len(walls))

    # The floor between them (20 cm or more from any wall, away from the car and its cones) is grey.
    points = [(x, y, 0.0) for x in np.linspace(min(xs), max(xs), 25) for y in np.linspace(min(ys), max(ys), 15)
              if min(distance_to_box((x, y), w) for w in walls) >= 0.2 and math.hypot(x, y) >= 0.5]
    floor = 0
    for (x, y, _), pixels in zip(points, pixels_at(driver, image, points)):
        if pixels is None:
            continue
        floor += 1
        assert np.ptp(pixels[4]) < 30 and pixels[4][0] > 100, 'the floor at (%.2f, %.2f) is drawn %s' % (
            x, y, pixels[4])
    assert floor > 100


@pytest.mark.slow
def test_the_cars_drawn_pose_follows_model_states_as_it_drives(page, ros):
    from tianracer_description.tianracer import TUTORIAL_CONTROLLERS
    _, _, driver, _ = page
    ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=/tianracer', *TUTORIAL_CONTROLLERS], 'spawner')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS))
    start = driver.execute_script("return viewer.linkPose('tianracer::base_link')")
    # 1.5 s at 12 rad/s on the rear wheels (about 0.4 m/s), then stopped; the pose of the model then
    moved = ros.probe('viewer/probes/the_cars_drawn_pose_follows_model_states_as_it_drives.py', timeout=60)
    time.sleep(0.5)  # a few of the page's 30 pose updates a second
    drawn = driver.execute_script("return viewer.linkPose('tianracer::base_link')")
    assert math.hypot(moved[0] - start[0], moved[1] - start[1]) > 0.2, 'the car did not drive: %s' % moved
    # base_link is above base_footprint, the model's pose: the same x and y
    assert math.hypot(drawn[0] - moved[0], drawn[1] - moved[1]) < 0.01, (drawn, moved)


@pytest.mark.slow
def test_a_page_that_goes_away_leaves_the_scenes_link_states_unsubscribed(page, ros):
    _, _, driver, url = page

    def subscribed():
        info = ros.run(['rostopic', 'info', '/gazebo/scene_link_states']).stdout
        return '/viewer' in info.split('Subscribers:')[-1]

    assert subscribed()
    driver.get('about:blank')
    ros.wait_until(lambda: not subscribed(), 15, 'the viewer to drop /gazebo/scene_link_states')
    driver.get(url)
    ros.wait_until(subscribed, 15, 'the viewer to subscribe again for a new page')


def test_the_viewer_serves_only_the_scenes_files(page):
    import urllib.error
    import urllib.request
    _, _, _, url = page
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(url + 'files/etc/passwd', timeout=10)
    assert refused.value.code == 404
    with urllib.request.urlopen(url, timeout=10) as index:
        assert b'viewer.js' in index.read()
    with urllib.request.urlopen(url + 'viewer.js', timeout=10) as bundle:
        assert len(bundle.read()) > 100000  # three.js bundled: nothing fetched from the internet


def test_the_mesh_tracks_collada_floor_and_stl_walls_are_drawn_where_the_plant_has_them(ros, chromium, monkeypatch):
    """A Gazebo user's package (test/fixtures/gazebo_pkg): a Collada floor written in centimetres with
    z up and STL walls, included by model:// and lifted 0.5 m. Looked at from above, each point is
    drawn in the colour of what the plant's own ray from above hits there: the walls' red, the
    floor's dark grey (its Collada colour), the ground's light grey."""
    from plant_helpers import TRACK_WORLD, find_fixture_packages
    from tianracer_description import bullet_plant
    find_fixture_packages(monkeypatch)
    ros.env['ROS_PACKAGE_PATH'] = os.environ['ROS_PACKAGE_PATH']
    plant = bullet_plant.World.from_file(TRACK_WORLD)
    plant.echo = False
    driver = chromium
    with opened(ros, driver, TRACK_WORLD):
        eye = look_from_above(driver, (-1.0, -2.5), (13.0, 2.5))
        image = screenshot(driver)

        def seen_from_eye(x, y):
            """What the plant's ray from the viewer's eye towards (x, y, 0) hits: 'wall' (above the
            floor), 'floor' (its top, 0.5 m) or 'ground', and where."""
            direction = np.array([x, y, 0.0]) - eye
            direction /= np.linalg.norm(direction)
            hit = eye + plant.cast_ray(list(eye), list(direction), 100.0) * direction
            return ('wall' if hit[2] > 0.51 else 'floor' if hit[2] > 0.49 else 'ground'), hit

        grid = [(x, y) for x in np.linspace(-1.0, 13.0, 57) for y in np.linspace(-2.5, 2.5, 101)]
        hits = [seen_from_eye(x, y) for x, y in grid]
        assert all(np.all(np.isfinite(h[1])) for h in hits), 'every ray hits something: the ground is everywhere'
        seen = {'wall': 0, 'floor': 0, 'ground': 0}
        for ((x, y), (what, _)), pixels in zip(zip(grid, hits), pixels_at(driver, image, [h for _, h in hits])):
            if pixels is None:
                continue
            if what == 'wall':  # a wall (a few pixels wide, its edges blended)
                seen['wall'] += 1
                reddest = pixels[np.argmax(pixels[:, 0] - pixels[:, 1:].max(axis=1))]
                assert reddest[0] > reddest[1] + 60, 'the wall at (%.2f, %.2f) is drawn %s' % (x, y, pixels)
                continue
            if any(seen_from_eye(x + dx, y + dy)[0] != what for dx, dy in ((0.1, 0), (-0.1, 0), (0, 0.1), (0, -0.1))):
                continue  # by a wall or an edge of the floor: blended
            centre = pixels[4]
            if what == 'floor':  # its Collada colour 0.3 0.3 0.32, lit from above
                seen['floor'] += 1
                assert np.ptp(centre) < 20 and 50 < centre[0] < 100, (
                    'the floor at (%.2f, %.2f) is drawn %s' % (x, y, centre))
            else:  # the ground plane: 0.7 grey
                seen['ground'] += 1
                assert np.ptp(centre) < 20 and centre[0] > 130, 'the ground at (%.2f, %.2f) is drawn %s' % (
                    x, y, centre)
        assert min(seen.values()) > 20, seen


@pytest.mark.slow
def test_pause_stops_the_clock_play_starts_it_and_reset_world_puts_the_car_back(page):
    from selenium.webdriver.common.by import By
    ros, _, driver, _ = page
    wait_for(driver, 'viewer.status().paused === false && viewer.status().real_time_factor > 0.5', 15,
             'the status: running, near real time')
    driver.find_element(By.ID, 'pause').click()
    wait_for(driver, 'viewer.status().paused === true', 15, 'the page to show paused')
    before, after = ros.probe('viewer/probes/clock_twice.py')
    assert before == after, '/clock went on while paused: %s -> %s' % (before, after)
    wait_for(driver, 'viewer.status().real_time_factor === 0', 15, 'the real time factor to fall to 0')
    driver.find_element(By.ID, 'play').click()
    wait_for(driver, 'viewer.status().paused === false', 15, 'the page to show running')
    before, after = ros.probe('viewer/probes/clock_twice.py')
    assert after - before > 0.5, '/clock stood after play: %s -> %s' % (before, after)

    ros.service('/gazebo/set_model_state', "{model_state: {model_name: tianracer, pose: {position: {x: 1.0, y: 0.5, "
                                           "z: 0.05}, orientation: {w: 1.0}}}}")
    wait_for(driver, "viewer.linkPose('tianracer::base_link')[0] > 0.9", 15, 'the page to draw the car moved')
    driver.find_element(By.ID, 'reset_world').click()
    wait_for(driver, "Math.hypot(...viewer.linkPose('tianracer::base_link').slice(0, 2)) < 0.05", 15,
             'the page to draw the car back where it was spawned')


@pytest.mark.slow
def test_the_step_button_runs_the_iterations_asked_for_while_paused(page):
    """gzclient's step: paused, 250 iterations typed in and step clicked advance the clock by 0.25 s and
    leave it paused; the car's pose, lifted and let fall, changes only while stepping."""
    from selenium.webdriver.common.by import By
    ros, _, driver, _ = page
    driver.find_element(By.ID, 'pause').click()
    wait_for(driver, 'viewer.status().paused === true', 15, 'the page to show paused')
    ros.service('/gazebo/set_model_state', "{model_state: {model_name: tianracer, pose: {position: {z: 0.5}, "
                                           "orientation: {w: 1.0}}}}")
    wait_for(driver, "viewer.linkPose('tianracer::base_link')[2] > 0.45", 15, 'the page to draw the car lifted')
    before = driver.execute_script('return viewer.status().time')
    box = driver.find_element(By.ID, 'step_iterations')
    box.clear()
    box.send_keys('250')
    driver.find_element(By.ID, 'step').click()
    wait_for(driver, 'viewer.status().time >= %r' % (before + 0.2495), 15, 'the clock to advance by the steps')
    time.sleep(1.0)
    status = driver.execute_script('return viewer.status()')
    assert status['time'] == pytest.approx(before + 0.25, abs=1e-9) and status['paused'] is True, status
    # 0.25 s of free fall from 0.5 m: 0.31 m down; the page shows the last step's pose, as the plant has it
    height = driver.execute_script("return viewer.linkPose('tianracer::base_link')[2]")
    state = ros.service('/gazebo/get_link_state', '{link_name: "tianracer::base_link"}')
    assert height == pytest.approx(state['link_state']['pose']['position']['z'], abs=1e-6) and 0.15 < height < 0.25, (
        height, state)


def test_the_contacts_overlay_draws_the_tyres_contacts_under_the_wheels(page):
    """/gazebo/scene_contacts ticked: a point and its normal under each of the four wheels, on the
    ground, where the page draws the wheels; unticked, the viewer drops the topic."""
    from selenium.webdriver.common.by import By
    ros, _, driver, _ = page
    topic = '/gazebo/scene_contacts'
    box = tick_overlay(driver, topic, 'the contacts')
    points = driver.execute_script("return viewer.overlayPointsInWorld('%s')" % topic)
    wheels = [driver.execute_script("return viewer.linkPose('tianracer::%s')" % w)
              for w in ('left_front_wheel', 'right_front_wheel', 'left_rear_wheel', 'right_rear_wheel')]
    assert len(points) == 4, points
    for p in points:
        assert abs(p[2]) < 0.002, 'on the ground: %s' % p
        assert min(math.hypot(p[0] - w[0], p[1] - w[1]) for w in wheels) < 0.01, 'under a wheel: %s' % p
    assert min(min(math.hypot(p[0] - w[0], p[1] - w[1]) for p in points) for w in wheels) < 0.01, 'each wheel'

    def viewer_subscribes():
        return '/viewer' in ros.run(['rostopic', 'info', topic]).stdout.split('Subscribers:')[-1]
    assert viewer_subscribes()
    driver.find_element(By.CSS_SELECTOR, box).click()
    ros.wait_until(lambda: not viewer_subscribes(), 15, 'the viewer to drop the contacts')


def test_empty_world_launch_gui_true_starts_the_viewer_and_prints_where(ros):
    """gazebo_ros's gui:=true starts gzclient; here it starts the viewer (no desktop: no browser)."""
    import urllib.request
    from ros_harness import free_port
    from tianracer_description.tianracer import RACE_TRACK_WORLD
    port = free_port()
    launch = ros.start(['roslaunch', 'gazebo_ros', 'empty_world.launch', 'gui:=true', 'viewer_port:=%d' % port,
                        'world_name:=' + RACE_TRACK_WORLD], 'plant')
    url = 'http://127.0.0.1:%d/' % port
    ros.wait_until(lambda: ('viewer: open ' + url) in launch.log(), 60, 'the launch to print the viewer address')
    with urllib.request.urlopen(url, timeout=10) as index:
        assert b'viewer.js' in index.read()
    assert 'rviz' not in ros.run(['rosnode', 'list']).stdout


@pytest.mark.slow
def test_teleop_keys_in_the_page_drive_the_car_through_the_converter_and_letting_go_stops_it(page):
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select
    from tianracer_description.tianracer import TUTORIAL_CONTROLLERS
    ros, _, driver, _ = page
    ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=/tianracer', *TUTORIAL_CONTROLLERS], 'spawner')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS))
    ros.start(['rosrun', 'tianracer_description', 'cmdvel2gazebo.py'], 'cmdvel2gazebo')
    wait_for(driver, "Array.from(document.getElementById('drive_topic').options)"
                     ".some((o) => o.value === '/tianracer/cmd_vel')", 30, "the converter's topic to be offered")
    Select(driver.find_element(By.ID, 'drive_topic')).select_by_value('/tianracer/cmd_vel')
    driver.execute_script('document.activeElement.blur()')
    def model_xy():
        position = ros.model_pose('tianracer')['position']
        return position['x'], position['y']
    start = model_xy()
    ActionChains(driver).key_down('i').pause(2.0).key_up('i').perform()  # i: straight ahead
    driven = at_rest(model_xy)  # the converter's 0.2 s and the car rolling out
    assert driven[0] - start[0] > 0.3, 'the car did not drive ahead: %s -> %s' % (start, driven)


@pytest.mark.slow
def test_a_camera_overlay_shows_the_cameras_frames_and_is_unsubscribed_when_turned_off(page):
    import base64
    from PIL import Image
    from selenium.webdriver.common.by import By
    ros, _, driver, _ = page
    topic = '/camera/image_raw'
    box = tick_overlay(driver, topic, 'the camera')
    source = driver.execute_script("return document.querySelector('#images figure[data-topic=\"%s\"] img').src" % topic)
    shown = np.asarray(Image.open(io.BytesIO(base64.b64decode(source.split(',', 1)[1]))).convert('RGB'), dtype=float)
    # the same camera's frame straight from the topic (the car stands: the same view, other noise)
    frame = ros.probe('viewer/probes/camera_frame_mean.py', topic)
    assert frame['encoding'] == 'rgb8'
    assert [shown.shape[1], shown.shape[0]] == frame['size']
    assert np.abs(shown.reshape(-1, 3).mean(axis=0) - frame['mean']).max() < 6, (
        shown.reshape(-1, 3).mean(axis=0), frame['mean'])

    def viewer_subscribes():
        return '/viewer' in ros.run(['rostopic', 'info', topic]).stdout.split('Subscribers:')[-1]
    assert viewer_subscribes()
    driver.find_element(By.CSS_SELECTOR, box).click()
    ros.wait_until(lambda: not viewer_subscribes(), 15, 'the viewer to drop the camera')


@pytest.mark.slow
def test_a_lidar_overlay_draws_the_scans_hits_on_the_walls(page):
    """The car's lidar ticked: its hit points, drawn in its link as the page poses it, lie on the race
    track's walls and cones (within 5 cm: five standard deviations of the lidar's 1 cm noise; at three,
    a scan's 1081 draws pass it now and then: one point at 3.16 cm in the first scan of stop 50's
    noise engine)."""
    from tianracer_description.tianracer import RACE_TRACK_WORLD
    _, _, driver, _ = page
    topic = '/scan'
    tick_overlay(driver, topic, 'the lidar')
    points = driver.execute_script("return viewer.overlayPointsInWorld('%s')" % topic)
    walls = track_walls(RACE_TRACK_WORLD)
    cones = [(tuple(map(float, m.findtext('pose').split()[:2])), float(m.findtext('link/collision/geometry/cylinder/radius')))
             for m in ET.parse(RACE_TRACK_WORLD).getroot().iter('model')
             if m.find('link/collision/geometry/cylinder') is not None]
    assert len(points) > 500

    def off_everything(p):
        return (min(distance_to_box(p, w) for w in walls) > 0.05 and
                all(abs(math.hypot(p[0] - c[0], p[1] - c[1]) - r) > 0.05 for c, r in cones))
    off = [p for p in points if off_everything(p)]
    assert not off, '%d of %d points off the walls and cones, e.g. %s' % (len(off), len(points), off[:3])


@pytest.mark.slow
def test_a_ticked_sensor_stays_ticked_when_another_robots_sensor_comes(page):
    """The page makes its sensor list again when a topic comes: the car's lidar, ticked before a
    second robot with a lidar is spawned, stays ticked and drawn."""
    from plant_helpers import DIFF_BOT
    ros, _, driver, _ = page
    tick_overlay(driver, '/scan', 'the lidar')
    ros.set_param('/bot_description', textfile=DIFF_BOT)
    spawn = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-urdf', '-param', 'bot_description', '-model', 'bot',
                     '-robot_namespace', 'bot', '-x', '1.5'], timeout=60)
    assert spawn.returncode == 0, spawn.stdout + spawn.stderr
    wait_for(driver, "!!document.querySelector('#overlay_topics input[data-topic=\"/bot/scan\"]')", 30,
             "the second robot's lidar to be offered")
    assert driver.execute_script("return document.querySelector('#overlay_topics input[data-topic=\"/scan\"]').checked")
    drawn = driver.execute_script("return viewer.overlayFrames('/scan')")
    wait_for(driver, "viewer.overlayFrames('/scan') >= %d" % (drawn + 2), 30, "the car's lidar still drawn")


@pytest.mark.slow
def test_a_model_dragged_in_move_mode_is_where_get_model_state_says(page):
    """The model list's move, then a drag in the view: the car goes where it is dropped (set_model_state),
    and the list shows its new pose."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    ros, _, driver, _ = page
    look_from_above(driver, (-1.5, -1.5), (1.5, 1.5))
    driver.find_element(By.CSS_SELECTOR, '#models .model[data-model="tianracer"] button.move').click()
    start = driver.execute_script("return viewer.linkPose('tianracer::base_footprint')")
    project = 'return viewer.project(arguments[0], arguments[1], arguments[2])'
    a = driver.execute_script(project, start[0], start[1], start[2])
    b = driver.execute_script(project, start[0] + 0.8, start[1] + 0.4, start[2])
    canvas = driver.find_element(By.ID, 'view')
    ActionChains(driver).move_to_element_with_offset(canvas, int(a[0] - canvas.size['width'] / 2),
                                                     int(a[1] - canvas.size['height'] / 2)).click_and_hold() \
        .move_by_offset(int(round(b[0] - a[0])), int(round(b[1] - a[1]))).release().perform()
    moved = None
    deadline = time.monotonic() + 15
    while time.monotonic() < deadline:
        p = ros.service('/gazebo/get_model_state', '{model_name: tianracer}')['pose']['position']
        moved = (p['x'], p['y'])
        if math.hypot(moved[0] - start[0] - 0.8, moved[1] - start[1] - 0.4) < 0.03:
            break
        time.sleep(0.3)
    assert math.hypot(moved[0] - start[0] - 0.8, moved[1] - start[1] - 0.4) < 0.03, (start, moved)
    wait_for(driver, "document.querySelector('#models .model[data-model=\"tianracer\"] .pose').textContent"
                     ".startsWith('x %.2f')" % moved[0], 15, 'the model list to show the new pose')


@pytest.mark.slow
def test_a_followed_model_stays_where_it_is_drawn_as_it_moves(page):
    from selenium.webdriver.common.by import By
    ros, _, driver, _ = page
    # paused, no poses come but the one after the move: the page must follow from the tick on
    ros.service('/gazebo/pause_physics')
    time.sleep(0.3)  # the poses already on their way drawn
    driver.find_element(By.CSS_SELECTOR, '#models .model[data-model="tianracer"] input.follow').click()
    drawn = "const p = viewer.linkPose('tianracer::base_footprint'); return viewer.project(p[0], p[1], p[2])"
    before = driver.execute_script(drawn)
    ros.service('/gazebo/set_model_state', "{model_state: {model_name: tianracer, pose: {position: {x: 1.5, y: -0.3, "
                                           "z: 0.05}, orientation: {w: 1.0}}}}")
    # the follow moves the camera with the poses it draws: the moment the pose is there, so is it
    wait_for(driver, "viewer.linkPose('tianracer::base_footprint')[0] > 1.4", 15, 'the page to draw the car moved')
    after = driver.execute_script(drawn)
    assert math.hypot(after[0] - before[0], after[1] - before[1]) < 3, (before, after)  # pixels


@pytest.mark.slow
def test_a_diff_drive_robot_in_the_arena_is_drawn_and_driven_by_the_keys_on_its_cmd_vel(ros, chromium):
    """The other world we ship (worlds/arena.world) and a turtlebot3-like robot (gazebo_plugins' diff
    drive on /cmd_vel, test/fixtures/urdf/diff_bot.urdf): its links drawn where link_states puts
    them, and holding i on its cmd_vel drives it ahead; letting go stops it (the diff drive plugin has
    no timeout of its own: the viewer's zero command does it)."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select
    from plant_helpers import DIFF_BOT
    from ros_harness import spawn_urdf
    from tianracer_description.tianracer import PACKAGE
    arena = os.path.join(PACKAGE, 'worlds', 'arena.world')
    driver = chromium
    with opened(ros, driver, arena) as (plant, _, _):
        ros.set_param('/robot_description', textfile=DIFF_BOT)
        spawn_urdf(ros, plant, '/robot_description', 'diff_bot')
        wait_for(driver, "!!viewer.linkPose('diff_bot::base_link') && "
                         "!!document.querySelector('#models .model[data-model=\"diff_bot\"]')", 30,
                 'the spawned robot in the page')
        wait_for(driver, "Array.from(document.getElementById('drive_topic').options)"
                         ".some((o) => o.value === '/cmd_vel')", 30, 'its cmd_vel to be offered')
        Select(driver.find_element(By.ID, 'drive_topic')).select_by_value('/cmd_vel')
        driver.execute_script('document.activeElement.blur()')
        # z seven times: teleop's 1 m/s down to 0.48 m/s, a turtlebot's pace (at 1 m/s it rocks on
        # its caster for seconds after it stops)
        ActionChains(driver).send_keys('zzzzzzz').perform()
        wait_for(driver, "document.getElementById('drive_state').textContent.startsWith('speed 0.48')", 5,
                 'the speed scaled down')
        start = driver.execute_script("return viewer.linkPose('diff_bot::base_footprint')")
        ActionChains(driver).key_down('i').pause(2.0).key_up('i').perform()
        driven = at_rest(lambda: driver.execute_script("return viewer.linkPose('diff_bot::base_footprint')"))
        state = ros.service('/gazebo/get_model_state', '{model_name: diff_bot}')['pose']['position']
    assert math.hypot(driven[0] - start[0], driven[1] - start[1]) > 0.2, (start, driven)
    assert math.hypot(driven[0] - state['x'], driven[1] - state['y']) < 0.01, (driven, state)
