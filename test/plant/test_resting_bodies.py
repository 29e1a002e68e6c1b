"""Free models that come to rest sleep, as ODE's auto-disable puts Gazebo's resting bodies to sleep, and
wake when anything acts on them: a moving body's touch, a wrench, a new state, a new gravity. A model
with controllers never sleeps. Free 0.2 m boxes (1 kg, friction 1) in the plant's default world
(ground plane at z = 0, 1 ms steps, g = 9.8)."""
import numpy as np
import pytest

from tianracer_description import bullet_plant as bp
from tianracer_description.tianracer import REAR_WHEEL_CONTROLLERS, TUTORIAL_CONTROLLERS

SIZE = 0.2


def box_sdf(name):
    i = SIZE * SIZE / 6  # a 1 kg cube's inertia about an axis through its centre
    geometry = f'<geometry><box><size>{SIZE} {SIZE} {SIZE}</size></box></geometry>'
    return (f'<?xml version="1.0"?><sdf version="1.7"><model name="{name}"><link name="link">'
            f'<inertial><mass>1</mass><inertia><ixx>{i}</ixx><iyy>{i}</iyy><izz>{i}</izz></inertia></inertial>'
            f'<collision name="c">{geometry}<surface><friction><ode><mu>1</mu><mu2>1</mu2></ode></friction></surface>'
            '</collision></link></model></sdf>')


def world_with_boxes(positions):
    w = bp.World()
    w.echo = False
    boxes = [w.spawn(box_sdf(f'box_{k}'), f'box_{k}', [x, y, z, 0, 0, 0]) for k, (x, y, z) in enumerate(positions)]
    return w, boxes


def steps_until(w, condition, limit):
    """Steps until condition() holds (checked every 10 ms); returns the simulated seconds it took, or None."""
    start = w.time
    while w.time - start < limit:
        w.step(10)
        if condition():
            return w.time - start
    return None


def test_resting_boxes_fall_asleep_within_two_seconds():
    w, boxes = world_with_boxes([(x, 0, SIZE / 2 + 0.001) for x in (-1, 0, 1)])
    assert not any(b.asleep for b in boxes)
    took = steps_until(w, lambda: all(b.asleep for b in boxes), 2.5)
    assert took is not None and took < 2.0, took
    poses = np.array([b.base_pose() for b in boxes])
    w.step(500)  # asleep: they stay exactly where they are
    assert np.array_equal(np.array([b.base_pose() for b in boxes]), poses)
    assert all(b.asleep for b in boxes)
    assert all(p[2] == pytest.approx(SIZE / 2, abs=2e-3) for p in poses)


def test_a_box_dropped_on_a_sleeping_one_wakes_it_and_both_settle():
    w, (below,) = world_with_boxes([(0, 0, SIZE / 2 + 0.001)])
    assert steps_until(w, lambda: below.asleep, 2.5) is not None
    above = w.spawn(box_sdf('above'), 'above', [0, 0, 0.6, 0, 0, 0])
    assert steps_until(w, lambda: not below.asleep, 0.5) is not None  # woken by the impact
    assert steps_until(w, lambda: below.asleep and above.asleep, 4.0) is not None
    assert below.base_pose()[2] == pytest.approx(SIZE / 2, abs=3e-3)
    assert above.base_pose()[2] == pytest.approx(1.5 * SIZE, abs=5e-3)
    assert abs(above.base_pose()[0]) < 0.05  # it landed on the box, not beside it


def test_a_wrench_on_a_sleeping_box_moves_it():
    w, (box,) = world_with_boxes([(0, 0, SIZE / 2 + 0.001)])
    assert steps_until(w, lambda: box.asleep, 2.5) is not None
    x = box.base_pose()[0]
    box.apply_link_wrench('link', [30, 0, 0], start=w.time, duration=0.2)  # 3 g against mu g: it slides
    w.step(1)
    assert not box.asleep
    w.step(300)
    assert box.base_pose()[0] - x > 0.1


def test_set_link_state_wakes_a_sleeping_box_which_falls_and_rests_again():
    w, (box,) = world_with_boxes([(0, 0, SIZE / 2 + 0.001)])
    assert steps_until(w, lambda: box.asleep, 2.5) is not None
    box.set_link_state('link', [0.5, 0, 1.0, 0, 0, 0, 1])
    assert not box.asleep
    w.step(200)
    assert box.base_pose()[2] < 0.85  # falling: 1 - g t^2 / 2 = 0.80 m at 0.2 s
    assert steps_until(w, lambda: box.asleep, 4.0) is not None
    # where it was put (a corner-first landing may slide it a little; see test_sdf_physics.py)
    assert list(box.base_pose()[:3]) == pytest.approx([0.5, 0, SIZE / 2], abs=0.03)


def test_reset_world_and_gravity_wake_sleeping_boxes():
    w, (box,) = world_with_boxes([(0, 0, 0.5)])
    assert steps_until(w, lambda: box.asleep, 3.0) is not None
    w.reset_world()  # back to its spawn pose, 0.5 m up: it must fall again
    assert not box.asleep
    w.step(300)
    assert box.base_pose()[2] < 0.45
    assert steps_until(w, lambda: box.asleep, 3.0) is not None
    w.gravity = [0, 0, 9.8]  # upside down: it leaves the floor
    assert not box.asleep
    w.step(300)
    assert box.base_pose()[2] > SIZE / 2 + 0.3


def test_a_pile_comes_to_rest_and_sleeps_as_one():
    # 27 boxes in three layers: their contacts join them into one group of rows, more than the
    # solver's dense blocks take, so this is the sparse form's solve.
    pitch = SIZE + 0.02
    positions = [((i - 1) * pitch, (j - 1) * pitch, 0.3 + k * pitch) for k in range(3) for j in range(3) for i in range(3)]
    w, boxes = world_with_boxes(positions)
    assert steps_until(w, lambda: all(b.asleep for b in boxes), 5.0) is not None
    heights = sorted(b.base_pose()[2] for b in boxes)
    assert heights[0] == pytest.approx(SIZE / 2, abs=5e-3)  # none sank into the floor
    assert heights[-1] == pytest.approx(2.5 * SIZE, abs=2e-2)  # three layers still


def test_a_box_and_a_moving_mesh_dropped_on_a_mesh_floor_lie_flat_and_sleep(tmp_path):
    # A house's floor is a mesh (AWS RoboMaker's bookstore: a 29 cm slab of 12 triangles): a box
    # or a moving mesh (its convex hull) lands on a triangle face, clipped against it in up to four
    # points as on a plane. With one point a step they landed on a corner and rocked for ever.
    floor = tmp_path / 'slab.obj'
    floor.write_text('v -5 -5 -0.3\nv 5 -5 -0.3\nv 5 5 -0.3\nv -5 5 -0.3\nv -5 -5 0\nv 5 -5 0\nv 5 5 0\nv -5 5 0\n'
                     'f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\n'
                     'f 3 8 7\nf 4 1 5\nf 4 5 8\n')
    crate = tmp_path / 'crate.obj'  # a 0.2 m cube as a mesh, moving: its hull
    crate.write_text('v -0.1 -0.1 -0.1\nv 0.1 -0.1 -0.1\nv 0.1 0.1 -0.1\nv -0.1 0.1 -0.1\nv -0.1 -0.1 0.1\n'
                     'v 0.1 -0.1 0.1\nv 0.1 0.1 0.1\nv -0.1 0.1 0.1\nf 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\n'
                     'f 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n')
    inertia = ''  # SDF's default, 1 kg m^2 about each axis, as models without <inertia> have it
    w = bp.World.from_sdf(f"""<sdf version="1.6"><world name="house">
<model name="floor"><static>true</static><link name="link"><collision name="c"><geometry><mesh><uri>{floor}</uri>
  </mesh></geometry></collision></link></model>
<model name="box"><pose>0 0 0.2 0 0 0</pose><link name="link"><inertial><mass>1</mass>{inertia}</inertial>
  <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model>
<model name="crate"><pose>1 0 0.2 0 0 0</pose><link name="link"><inertial><mass>1</mass>{inertia}</inertial>
  <collision name="c"><geometry><mesh><uri>{crate}</uri></mesh></geometry></collision></link></model>
</world></sdf>""")
    w.echo = False
    bodies = [w.robot('box'), w.robot('crate')]
    assert steps_until(w, lambda: all(b.asleep for b in bodies), 4.0) is not None, [b.base_pose() for b in bodies]
    for body in bodies:
        pose = body.base_pose()
        up = 1 - 2 * (pose[3] ** 2 + pose[4] ** 2)  # the body's z axis against the world's
        face_up = max(abs(up), abs(2 * (pose[3] * pose[5] + pose[4] * pose[6])),
                      abs(2 * (pose[4] * pose[5] - pose[3] * pose[6])))
        assert face_up > 1 - 1e-5, pose  # a face flat on the floor
        assert pose[2] == pytest.approx(0.1, abs=1.5e-3), pose  # on the floor, within its margins


def test_a_robot_with_controllers_never_sleeps(urdf_xml, control_config):
    w = bp.World()
    w.echo = False
    w.load_params(control_config)
    car = w.spawn(urdf_xml, 'tianracer')
    cm = car.controller_manager
    for name in TUTORIAL_CONTROLLERS:
        assert cm.load(name)
    assert cm.switch(start=list(TUTORIAL_CONTROLLERS))
    w.step(4000)  # at rest for 4 s: twice what puts a free box to sleep
    assert not car.asleep
    x = car.base_pose()[0]
    for name in REAR_WHEEL_CONTROLLERS:  # its controllers still run: it drives off at once
        cm.command(name, 10.0)
    w.step(500)
    assert car.base_pose()[0] - x > 0.1


def pile_run():
    positions = [(0.03 * k, 0.02 * k, 0.3 + 0.25 * k) for k in range(6)]
    w, boxes = world_with_boxes(positions)
    w.step(3000)
    return np.array([b.base_pose() for b in boxes]), [b.asleep for b in boxes]


def test_two_identical_runs_give_bit_identical_poses():
    (first, asleep_first), (second, asleep_second) = pile_run(), pile_run()
    assert np.array_equal(first, second)
    assert asleep_first == asleep_second
