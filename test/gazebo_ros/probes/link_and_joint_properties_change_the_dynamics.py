"""The ROS side of test_link_and_joint_properties.py, a rospy program the test runs against its own
master (ros.probe): a crate floating 1 m up and a spinner on a vertical axis, their properties got,
set and measured by pushing them for a known simulated time; it prints one JSON value on its last
line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
from gazebo_msgs.msg import ODEJointProperties
CRATE = """<sdf version="1.6"><model name="crate"><link name="body">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <collision name="shell"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model></sdf>"""
SPINNER = """<sdf version="1.6"><model name="spinner"><link name="arm">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.02</izz></inertia></inertial></link>
  <joint name="spin" type="revolute"><parent>world</parent><child>arm</child><axis><xyz>0 0 1</xyz></axis></joint>
</model></sdf>"""
world = srv('get_world_properties', GetWorldProperties)
spawn = srv('spawn_sdf_model', SpawnModel)
get_state = srv('get_model_state', GetModelState)
get_link = srv('get_link_properties', GetLinkProperties)
set_link = srv('set_link_properties', SetLinkProperties)
set_joint = srv('set_joint_properties', SetJointProperties)
get_joint = srv('get_joint_properties', GetJointProperties)
wrench = srv('apply_body_wrench', ApplyBodyWrench)
effort = srv('apply_joint_effort', ApplyJointEffort)
clear_efforts = srv('clear_joint_forces', JointRequest)
pause, unpause = srv('pause_physics', Empty), srv('unpause_physics', Empty)


def run_for(seconds):
    """Unpaused for that much simulated time, then paused again."""
    start = world().sim_time
    unpause()
    while world().sim_time < start + seconds:
        time.sleep(0.01)
    pause()


def link_props(name):
    p = get_link(name)
    return [result(p), p.mass, [p.ixx, p.iyy, p.izz, p.ixy, p.ixz, p.iyz], p.gravity_mode,
            [p.com.position.x, p.com.position.y, p.com.position.z, p.com.orientation.w]]


def set_props(name, mass, inertia, gravity, com=(0.0, 0.0, 0.0)):
    c = Pose()
    c.position.x, c.position.y, c.position.z = com
    c.orientation.w = 1
    return result(set_link(link_name=name, com=c, gravity_mode=gravity, mass=mass, ixx=inertia, iyy=inertia,
                           izz=inertia, ixy=0, ixz=0, iyz=0))


def push_x(newtons, seconds):
    """The crate's speed along x gained from a push of that force for that long."""
    before = get_state('crate', '').twist.linear.x
    wrench('crate::body', '', Point(), Wrench(force=Vector3(newtons, 0, 0)), rospy.Time(0), rospy.Duration(seconds))
    run_for(seconds + 0.05)
    return get_state('crate', '').twist.linear.x - before


out['spawn'] = [result(spawn('crate', CRATE, '', pose(0, 3, 1.0), '')),
                result(spawn('spinner', SPINNER, '', pose(0, -3, 1.0), ''))]
out['crate'] = link_props('crate::body')
out['unknown'] = link_props('crate::nothing')
# gravity off: the crate stays up
out['gravity_off'] = set_props('crate::body', 1.0, 0.01, False)
run_for(0.5)
out['floating_z'] = get_state('crate', '').pose.position.z
out['pushed_1kg'] = push_x(2.0, 0.5)
out['heavier'] = set_props('crate::body', 4.0, 0.04, False)
out['crate_after'] = link_props('crate::body')
out['pushed_4kg'] = push_x(2.0, 0.5)
# a new centre of mass is not taken: the link keeps its own
out['moved_com'] = set_props('crate::body', 4.0, 0.04, False, com=(0.05, 0.0, 0.0))
out['com_after'] = link_props('crate::body')[4]
out['negative_mass'] = set_props('crate::body', -1.0, 0.01, False)
out['nan_inertia'] = set_props('crate::body', 1.0, float('nan'), False)
out['gravity_on'] = set_props('crate::body', 4.0, 0.04, True)
z = get_state('crate', '').pose.position.z
run_for(0.2)
out['fell'] = z - get_state('crate', '').pose.position.z


def joint_config(**lists):
    c = ODEJointProperties()
    for key, values in lists.items():
        setattr(c, key, values)
    return c


rate = lambda: get_joint('spin').rate[0]
position = lambda: get_joint('spin').position[0]
out['joint_unknown'] = result(set_joint('nothing', joint_config(damping=[1.0])))
out['negative_damping'] = result(set_joint('spin', joint_config(damping=[-1.0])))
# damping 1 N m s/rad against 0.1 N m: 0.1 rad/s (undamped it would reach 7.5 rad/s in 1.5 s)
out['damping'] = result(set_joint('spin', joint_config(damping=[1.0])))
effort('spin', 0.1, rospy.Time(0), rospy.Duration(-1))
run_for(1.5)
out['damped_rate'] = rate()
clear_efforts('spin')
# ODE's joint motor: at most fmax towards vel (Gazebo's joint friction is this motor with vel 0)
out['motor'] = result(set_joint('spinner::spin', joint_config(damping=[0.0], fmax=[0.5], vel=[2.0])))
run_for(1.0)
out['motor_rate'] = rate()
# stops: the motor turns the joint against the high stop
out['stops'] = result(set_joint('spin', joint_config(loStop=[-0.1], hiStop=[0.1], erp=[0.2])))
srv('set_model_configuration', SetModelConfiguration)('spinner', '', ['spin'], [0.0])
run_for(1.0)
out['at_stop'] = position()
# lo > hi: no stops, as ODE's
out['no_stops'] = result(set_joint('spin', joint_config(loStop=[1.0], hiStop=[-1.0])))
run_for(0.5)
out['past_stop'] = position()
print(json.dumps(out))
