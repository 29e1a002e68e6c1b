"""gazebo_ros_bumper through the node: the bumper robot (test/fixtures/urdf/bumper_bot.urdf)
pushed into a wall by a Wrench on gazebo_ros_force's topic. What a bumper's users read of
gazebo_msgs/ContactsState: the pair of collisions, upstream's info text, each point's wrench and
their total, positions, normals and depths, in the plugin's frame and topic (and the defaults)."""
import os

import pytest

from plant_helpers import FIXTURES, box_model, sdf_world
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def test_bumper_states_of_a_robot_pushed_into_a_wall(ros, tmp_path):
    (tmp_path / 'wall.world').write_text(sdf_world(box_model('wall', (0.1, 2.0, 0.5), (0.34, 0, 0.25))))
    plant = start_plant(ros, str(tmp_path / 'wall.world'))
    ros.set_param('/robot_description', textfile=os.path.join(FIXTURES, 'urdf', 'bumper_bot.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'bumper_bot', xyz=(0, 0, 0.05))
    seen = ros.probe('sensor_plugins/probes/bumper_states_of_a_robot_pushed_into_a_wall.py', timeout=90)
    ground, before, after = seen['ground'], seen['before'], seen['after']
    assert ground['frame'] == 'world' and before['frame'] == 'bumper'
    [on_ground] = ground['states']
    assert (on_ground['c1'], on_ground['c2']) == ('bumper_bot::base_link::base_link_collision',
                                                  'ground_plane::link::collision')
    assert on_ground['total'] == pytest.approx([0, 0, 4.5 * 9.8], abs=0.01), 'the weight'
    assert on_ground['total'] == pytest.approx(on_ground['sum'], abs=1e-9), 'total_wrench sums the wrenches'
    assert before['states'] == [], 'nothing touches the bumper before the push'
    [on_wall] = after['states']
    assert on_wall['c1'] == 'bumper_bot::base_link::base_link_fixed_joint_lump__bumper_collision_1'
    assert on_wall['c2'] == 'wall::link::collision'
    assert on_wall['info'].startswith('Debug:  i:(0/1)     my geom:' + on_wall['c1'] + '   other geom:' +
                                      on_wall['c2'] + '         time:')
    assert on_wall['total'] == pytest.approx([-10.0, 0, 0], abs=0.01), 'the wall holds the 10 N push'
    for normal, position, depth in zip(on_wall['normals'], on_wall['positions'], on_wall['depths']):
        assert normal == pytest.approx([-1, 0, 0], abs=1e-6) and depth >= 0
        assert position[0] == pytest.approx(0.29, abs=1e-3), 'on the wall\'s face, in the world'
