"""The ROS side of test_physics_reconfigure.py, a rospy program the test runs against its own master
(ros.probe); it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
import dynamic_reconfigure.client
from dynamic_reconfigure.msg import Config
get = srv('get_physics_properties', GetPhysicsProperties)
set_physics = srv('set_physics_properties', SetPhysicsProperties)
client = dynamic_reconfigure.client.Client('/gazebo', timeout=30)
out['descriptions'] = {p['name']: [p['type'], p['level'], p['min'], p['max'], p['default']]
                       for p in client.get_parameter_descriptions()}
config = client.get_configuration(timeout=30)
p = get()
out['initial'] = [config['time_step'], config['max_update_rate'], config['gravity_z'], config['sor_pgs_iters'],
                  config['contact_max_correcting_vel']]
out['physics'] = [p.time_step, p.max_update_rate, p.gravity.z, p.ode_config.sor_pgs_iters,
                  p.ode_config.contact_max_correcting_vel]
updates = []
rospy.Subscriber('/gazebo/parameter_updates', Config, lambda m: updates.append(m))
changed = client.update_configuration({'gravity_z': -4.0, 'time_step': 0.002, 'sor_pgs_iters': 30,
                                        'sor_pgs_w': 1.2, 'contact_surface_layer': 0.002})
p = get()
out['changed'] = [changed['gravity_z'], changed['time_step'], changed['sor_pgs_iters']]
out['after'] = [p.gravity.z, p.time_step, p.ode_config.sor_pgs_iters, p.ode_config.sor_pgs_w,
                p.ode_config.contact_surface_layer, p.max_update_rate]
out['params'] = [rospy.get_param('/gazebo/gravity_z'), rospy.get_param('/gazebo/time_step')]
# a step the plant refuses: nothing changes, and the reply and parameter_updates say what holds
refused = client.update_configuration({'time_step': 0.0, 'gravity_z': -1.0})
p = get()
out['refused'] = [refused['time_step'], refused['gravity_z'], p.time_step, p.gravity.z]
time.sleep(0.5)
last = {d.name: d.value for d in updates[-1].doubles}
out['last_update'] = [last['time_step'], last['gravity_z']]
# set_physics_properties: the solver settings it honours, and one out of range refused whole
ode = p.ode_config
ode.sor_pgs_iters, ode.sor_pgs_w, ode.contact_surface_layer, ode.contact_max_correcting_vel = 40, 1.5, 0.003, 50.0
ode.erp, ode.max_contacts = 0.2, 20
out['set'] = result(set_physics(0.001, 1000.0, Vector3(0, 0, -9.8), ode))
p = get()
out['set_after'] = [p.time_step, p.gravity.z, p.ode_config.sor_pgs_iters, p.ode_config.sor_pgs_w,
                    p.ode_config.contact_surface_layer, p.ode_config.contact_max_correcting_vel]
ode.sor_pgs_iters = 0
out['no_passes'] = result(set_physics(0.002, 1000.0, Vector3(0, 0, -1.0), ode))
ode.sor_pgs_iters, ode.sor_pgs_w = 40, 2.5
out['sor_too_big'] = result(set_physics(0.002, 1000.0, Vector3(0, 0, -1.0), ode))
p = get()
out['unchanged'] = [p.time_step, p.gravity.z, p.ode_config.sor_pgs_iters]
print(json.dumps(out))
