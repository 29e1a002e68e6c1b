"""The node's ROS graph is gazebo_ros's (Noetic) and nothing more, as upstream's own API test lists it
(gazebo_ros_pkgs noetic-devel's gazebo_ros/test/ros_network/gazebo_network_api.yaml and
no_gazebo_network_api.yaml): empty_world.launch's
services and topics with their types and publishers; with `enable_ros_network:=false` only /clock
and roscpp's logger services of /gazebo, as Gazebo leaves them. The plant's viewer topics
(/gazebo/scene, scene_link_states, scene_contacts, step_physics) come once a node asks for one."""
import pytest

from ros_harness import start_plant

pytestmark = pytest.mark.ros

# gazebo_network_api.yaml: topic -> (type, publishers; None: any number)
GAZEBO_ROS_TOPICS = {
    '/clock': ('rosgraph_msgs/Clock', 1),
    '/rosout': ('rosgraph_msgs/Log', None),
    '/gazebo/set_model_state': ('gazebo_msgs/ModelState', 0),
    '/gazebo/set_link_state': ('gazebo_msgs/LinkState', 0),
    '/gazebo/link_states': ('gazebo_msgs/LinkStates', 1),
    '/gazebo/model_states': ('gazebo_msgs/ModelStates', 1),
    '/gazebo/parameter_descriptions': ('dynamic_reconfigure/ConfigDescription', 1),
    '/gazebo/parameter_updates': ('dynamic_reconfigure/Config', 1),
}
GAZEBO_ROS_SERVICES = {
    'apply_joint_effort': 'gazebo_msgs/ApplyJointEffort',
    'get_physics_properties': 'gazebo_msgs/GetPhysicsProperties',
    'set_link_state': 'gazebo_msgs/SetLinkState',
    'set_joint_properties': 'gazebo_msgs/SetJointProperties',
    'reset_world': 'std_srvs/Empty',
    'set_model_configuration': 'gazebo_msgs/SetModelConfiguration',
    'get_world_properties': 'gazebo_msgs/GetWorldProperties',
    'delete_light': 'gazebo_msgs/DeleteLight',
    'set_parameters': 'dynamic_reconfigure/Reconfigure',
    'spawn_sdf_model': 'gazebo_msgs/SpawnModel',
    'unpause_physics': 'std_srvs/Empty',
    'pause_physics': 'std_srvs/Empty',
    'get_joint_properties': 'gazebo_msgs/GetJointProperties',
    'set_logger_level': 'roscpp/SetLoggerLevel',
    'get_light_properties': 'gazebo_msgs/GetLightProperties',
    'clear_body_wrenches': 'gazebo_msgs/BodyRequest',
    'clear_joint_forces': 'gazebo_msgs/JointRequest',
    'set_physics_properties': 'gazebo_msgs/SetPhysicsProperties',
    'get_model_state': 'gazebo_msgs/GetModelState',
    'reset_simulation': 'std_srvs/Empty',
    'delete_model': 'gazebo_msgs/DeleteModel',
    'spawn_urdf_model': 'gazebo_msgs/SpawnModel',
    'set_link_properties': 'gazebo_msgs/SetLinkProperties',
    'set_model_state': 'gazebo_msgs/SetModelState',
    'apply_body_wrench': 'gazebo_msgs/ApplyBodyWrench',
    'get_link_state': 'gazebo_msgs/GetLinkState',
    'get_loggers': 'roscpp/GetLoggers',
    'get_model_properties': 'gazebo_msgs/GetModelProperties',
    'set_light_properties': 'gazebo_msgs/SetLightProperties',
    'get_link_properties': 'gazebo_msgs/GetLinkProperties',
}
# What the test's own roscore adds (rostest's has them too): rosout's aggregate and its logger services.
MASTER_TOPICS = {'/rosout_agg'}
MASTER_SERVICES = {'/rosout/get_loggers': 'roscpp/GetLoggers', '/rosout/set_logger_level': 'roscpp/SetLoggerLevel'}
VIEWER_TOPICS = ['/gazebo/scene', '/gazebo/scene_contacts', '/gazebo/scene_link_states', '/gazebo/step_physics']


def graph(ros, settle=5.0):
    return ros.probe('gazebo_ros/probes/the_graph_with_types.py', settle, timeout=120)


def test_the_graph_is_gazebo_ros_list_and_nothing_more(ros):
    plant = start_plant(ros)
    g = graph(ros)
    topics, services = g['topics'], g['services']
    assert set(topics) == set(GAZEBO_ROS_TOPICS) | MASTER_TOPICS, (sorted(topics), plant.log())
    for name, (kind, publishers) in GAZEBO_ROS_TOPICS.items():
        assert topics[name][0] == kind, name
        if publishers is not None:
            assert topics[name][1] == publishers, name
    expected = {'/gazebo/' + name: kind for name, kind in GAZEBO_ROS_SERVICES.items()}
    expected.update(MASTER_SERVICES)
    assert services == expected


def test_enable_ros_network_false_leaves_clock_and_the_logger_services(ros):
    """gazebo_ros's advertiseServices() is not called and its physics reconfigure never starts (it waits
    for set_physics_properties); /clock goes on and the world runs."""
    plant = ros.start(['roslaunch', 'gazebo_ros', 'empty_world.launch', 'gui:=false', 'enable_ros_network:=false'],
                      'plant')
    g = graph(ros)
    assert set(g['topics']) == {'/clock', '/rosout'} | MASTER_TOPICS, (g, plant.log())
    assert g['topics']['/clock'] == ['rosgraph_msgs/Clock', 1]
    expected = {'/gazebo/get_loggers': 'roscpp/GetLoggers', '/gazebo/set_logger_level': 'roscpp/SetLoggerLevel'}
    expected.update(MASTER_SERVICES)
    assert g['services'] == expected
    assert 'ROS gazebo topics/services are disabled' in plant.log()
    clock = ros.run(['rostopic', 'echo', '-n', '1', '/clock'], timeout=30).stdout
    assert 'secs' in clock


def test_the_viewers_topics_come_when_a_node_asks_for_them(ros):
    """None of them before (test_the_graph_is_gazebo_ros_list_and_nothing_more); a node subscribing to
    /gazebo/scene, as the viewer and scene_markers do, gets the latched scene within the node's 1 s
    look at the master, and the others come with it."""
    start_plant(ros)
    assert not set(graph(ros, settle=1.0)['topics']) & set(VIEWER_TOPICS)
    out = ros.probe('gazebo_ros/probes/viewer_topics_come_when_a_node_subscribes_to_the_scene.py', timeout=60)
    assert out['world'] == 'default'
    assert out['waited'] < 5.0
    assert set(VIEWER_TOPICS) - {'/gazebo/step_physics'} <= set(out['published'])
    assert '/gazebo/step_physics' in out['subscribed_by_others']
