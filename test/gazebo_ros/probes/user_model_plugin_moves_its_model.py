"""A user's Gazebo model plugin (test/fixtures/gazebo_plugin_pkg's libpush_model.so, found on the
library path) hosted by the plant from Python: two carts, one pushed along x at 0.3 m/s with its top
spun at 2 rad/s, one lifted by twice its weight with its top twisted by 0.004 N m, one whose joint its model's joint controller holds
at 1 rad, one whose joint's motor turns it at 1.5 rad/s, one floating and pushed off its centre, and one naming a library that is no Gazebo plugin
(the C maths library: it loads, but has no RegisterPlugin); 1 s of simulated time, then reset_world
(the plugins' Reset writes their counts to the report files), then one cart deleted and spawned
again 50 times. Prints the carts' motion as JSON."""
import json
import sys

from tianracer_description import bullet_plant

CART = """<?xml version="1.0"?>
<robot name="cart">
  <link name="base">
    <inertial><mass value="2.0"/><inertia ixx="0.02" iyy="0.03" izz="0.04" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.4 0.3 0.1"/></geometry></collision>
  </link>
  <link name="top">
    <inertial><origin xyz="0 0 0"/><mass value="0.2"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="spin_joint" type="continuous">
    <parent link="base"/><child link="top"/><origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
  </joint>
  <gazebo>
    <plugin name="push" filename="libpush_model.so">%s</plugin>
  </gazebo>
</robot>
"""


NOT_A_PLUGIN = '/lib/x86_64-linux-gnu/libm.so.6'


def main(report_dir):
    world = bullet_plant.World()
    world.echo = False
    pushed = world.spawn(CART % ('<speed>0.3</speed><joint>spin_joint</joint><spin>2.0</spin><report>%s/pushed.txt</report>'
                                 % report_dir), 'pushed_cart', pose=[0.0, 0.0, 0.06, 0, 0, 0])
    lifted = world.spawn(CART % ('<pushed>base</pushed><lift>43.164</lift><joint>spin_joint</joint><twist>0.004</twist>'
                                 '<report>%s/lifted.txt</report>' % report_dir),
                         'lifted_cart', pose=[0.0, 2.0, 0.06, 0, 0, 0])
    broken = world.spawn(CART.replace('libpush_model.so', NOT_A_PLUGIN) % '', 'broken_cart', pose=[0.0, 4.0, 0.5, 0, 0, 0])
    held = world.spawn(CART % '<joint>spin_joint</joint><target>1.0</target>', 'held_cart', pose=[0.0, 6.0, 0.06, 0, 0, 0])
    motored = world.spawn(CART % ('<joint>spin_joint</joint><motor_velocity>1.5</motor_velocity><motor_force>0.5'
                                  '</motor_force><report>%s/motored.txt</report>' % report_dir), 'motored_cart',
                          pose=[0.0, 10.0, 0.06, 0, 0, 0])
    # floating (its weight lifted), pushed along x at a point 0.15 m to its left: it turns right
    twisted = world.spawn(CART % '<pushed>base</pushed><lift>21.56</lift><push_at>0 0.15 0</push_at>'
                          '<push_force>0.5 0 0</push_force>', 'twisted_cart', pose=[0.0, 8.0, 1.0, 0, 0, 0])
    carts = {'pushed': pushed, 'lifted': lifted, 'broken': broken, 'twisted': twisted}
    start = {name: list(cart.base_pose()) for name, cart in carts.items()}
    world.step(int(round(1.0 / world.time_step)))
    end = {name: list(cart.base_pose()) for name, cart in carts.items()}
    spin = list(pushed.joint_state('spin_joint'))
    held_at = list(held.joint_state('spin_joint'))
    motor = list(motored.joint_state('spin_joint'))
    twisted_spin = list(lifted.joint_state('spin_joint'))
    world.reset_world()
    reports = {}
    for name in ('pushed', 'lifted', 'motored'):
        with open('%s/%s.txt' % (report_dir, name)) as f:
            reports[name] = f.read().split()
    # delete_model and spawn again, 50 times: each plugin goes with its model and a new one comes
    # with the next, which moves its own model (a plugin of a deleted model would crash the next step)
    for _ in range(50):
        world.remove('pushed_cart')
        respawned = world.spawn(CART % '<speed>0.3</speed>', 'pushed_cart', pose=[0.0, 0.0, 0.06, 0, 0, 0])
        world.step(10)
    respawned_x = respawned.base_pose()[0]
    print(json.dumps({'start': start, 'end': end, 'spin': spin, 'held': held_at, 'motor': motor, 'reports': reports,
                      'respawned_x': respawned_x, 'twisted_spin': twisted_spin,
                      'messages': world.messages()}, default=list))


if __name__ == '__main__':
    main(sys.argv[1])
