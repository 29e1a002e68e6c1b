"""gazebo_plugins' libgazebo_ros_f3d.so on the plant, through its Python module: the wrench added
to a link before it in the step, every step."""
import pytest

from plant_helpers import f3d_bot, logged, spawned


def test_f3d_reports_the_wrench_pushed_on_its_link_but_neither_gravity_nor_contacts():
    world, robot = spawned(f3d_bot(), name='pushed', namespace='/')
    assert robot.plugin_topics('f3d') == {'subscribes': [], 'publishes': ['force_truth']}
    world.step(200)  # resting on its wheels: weight and contacts act, nothing is added
    at_rest = robot.plugin_latest('f3d', 'force_truth')
    assert at_rest['frame_id'] == 'world' and at_rest['stamp'] == pytest.approx(world.time - 0.001, abs=1e-9)
    assert at_rest['force'] == [0, 0, 0] and at_rest['torque'] == [0, 0, 0]
    assert robot.plugin_send('push', 'force', (1.0, -2.0, 30.0, 0.0, 0.0, 0.5))
    world.step(3)
    pushed = robot.plugin_latest('f3d', 'force_truth')
    assert pushed['force'] == pytest.approx([1.0, -2.0, 30.0]) and pushed['torque'] == pytest.approx([0, 0, 0.5])
    world, robot = spawned(f3d_bot(frameName='/map', bodyName='nowhere'), name='pushed')
    assert robot.model_plugins == ['push'] and any("plugin 'f3d' (libgazebo_ros_f3d.so)" in m and "'nowhere'" in m
                                                  for m in logged(world, 'ERROR'))
    world, robot = spawned(f3d_bot(frameName='/map'), name='pushed')
    world.step(2)
    assert robot.plugin_latest('f3d', 'force_truth')['frame_id'] == 'map', 'tf::resolve drops the leading slash'
