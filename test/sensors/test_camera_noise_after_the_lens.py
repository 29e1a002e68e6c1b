"""A camera with a lens and noise adds the noise after the lens, as Gazebo's noise compositor follows
its distortion compositor (CameraSensor::Init sets the noise's camera after CreateRenderTexture
has added the distortion): each pixel of the published frame carries one noise sample of the
camera's stddev, independent of its neighbours', where the lens magnifies as well as where it does
not. Noise before the lens would be spread by the remap's bilinear taps (neighbours correlated, the
spread smaller where the lens magnifies)."""
import numpy as np
import pytest

from tianracer_description import bullet_plant

STDDEV = 0.05  # of the colour's 0..1 range: 12.75 levels of a byte


def camera_world(distortion):
    lens = '<distortion>%s<center>0.5 0.5</center></distortion>' % distortion if distortion else ''
    # nothing in view: every pixel is the background's grey before the noise
    return f"""<sdf version="1.6"><world name="w"><scene><background>0.5 0.5 0.5 1</background></scene>
<model name="eye"><static>true</static><pose>0 0 1 0 0 0</pose><link name="link">
<sensor name="camera" type="camera"><update_rate>10</update_rate><camera><horizontal_fov>1.2</horizontal_fov>
<image><width>160</width><height>120</height></image><clip><near>0.05</near><far>5</far></clip>
<noise><type>gaussian</type><mean>0</mean><stddev>{STDDEV}</stddev></noise>{lens}</camera></sensor>
</link></model></world></sdf>"""


def frame(distortion):
    world = bullet_plant.World.from_sdf(camera_world(distortion))
    world.echo = False
    eye = world.robot('eye')
    eye.enable_sensor('camera')
    world.step(100)
    return eye.image('camera')['rgb'].astype(float)


@pytest.mark.parametrize('distortion', ['', '<k1>-0.5</k1>', '<k1>0.5</k1>'], ids=['no lens', 'barrel', 'pincushion'])
def test_each_pixel_takes_one_noise_sample_after_the_lens(distortion):
    rgb = frame(distortion)
    # the centre, where a barrel lens magnifies and a pincushion lens shrinks
    centre = rgb[40:80, 50:110, 0] - 127.5
    assert np.std(centre) == pytest.approx(255 * STDDEV, rel=0.15)
    # one sample on red, green and blue alike (Gazebo's shader adds one to the three)
    assert np.array_equal(rgb[..., 0], rgb[..., 1]) and np.array_equal(rgb[..., 0], rgb[..., 2])
    # neighbours' noise independent: no remap spread it
    right = np.corrcoef(centre[:, :-1].ravel(), centre[:, 1:].ravel())[0, 1]
    down = np.corrcoef(centre[:-1, :].ravel(), centre[1:, :].ravel())[0, 1]
    assert abs(right) < 0.1 and abs(down) < 0.1, (right, down)
