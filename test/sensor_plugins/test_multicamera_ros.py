"""gazebo_ros_multicamera through the node: a stereo pair on a mast (test/fixtures/urdf/
stereo_mast.urdf) looking at a red post 2 m ahead before a grey wall. The left and right images on
<cameraName>/left and /right, one frame id for both, the right camera's CameraInfo carrying
-fx * hackBaseline, the post shifted between the images by the disparity fx * baseline / depth, and
a third camera (named neither left nor right) never published, as upstream."""
import os

import pytest

from plant_helpers import FIXTURES, sdf_world
from ros_harness import spawn_urdf, start_plant
from test_velodyne_ros import wall

pytestmark = pytest.mark.ros

POST_X, BASELINE = 2.0, 0.07


def red_post(x):
    geometry = '<geometry><box><size>0.05 0.05 2.0</size></box></geometry>'
    return f"""<model name="post"><static>true</static><pose>{x} 0 1.0 0 0 0</pose>
  <link name="link"><collision name="collision">{geometry}</collision>
    <visual name="visual">{geometry}<material><ambient>1 0 0 1</ambient><diffuse>1 0 0 1</diffuse></material></visual>
  </link>
</model>"""


def test_stereo_pair_left_and_right_with_their_disparity(ros, tmp_path):
    (tmp_path / 'post.world').write_text(sdf_world(wall(xyz=(4.0, 0.0, 1.5)) + red_post(POST_X)))
    plant = start_plant(ros, str(tmp_path / 'post.world'))
    ros.set_param('/robot_description', textfile=os.path.join(FIXTURES, 'urdf', 'stereo_mast.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'stereo_mast')
    seen = ros.probe('sensor_plugins/probes/stereo_pair_left_and_right_with_their_disparity.py', timeout=90)
    assert '/stereo/left/image_raw' in seen['topics'] and '/stereo/right/camera_info' in seen['topics']
    assert not [t for t in seen['topics'] if 'middle' in t], 'a camera named neither left nor right: nothing'
    left, right = seen['left'], seen['right']
    assert left['frame'] == right['frame'] == 'stereo_optical', 'one frameName for both, as upstream'
    assert left['size'] == right['size'] == [160, 120, 'rgb8']
    fx = left['K'][0]
    assert fx == pytest.approx(80 / 0.5773, rel=1e-3)  # width / (2 tan(hfov / 2))
    assert left['P'][3] == 0.0, "upstream fixes the left camera's baseline at 0"
    assert right['P'][3] == pytest.approx(-fx * BASELINE)
    assert left['red'] and right['red'], 'both see the post'
    centre = lambda columns: (min(columns) + max(columns)) / 2
    # The post on the left camera's axis; the right camera, 7 cm to the right, sees it shifted left.
    assert centre(left['red']) == pytest.approx(79.5, abs=0.6)
    assert centre(left['red']) - centre(right['red']) == pytest.approx(fx * BASELINE / (POST_X - 0.025), abs=0.8)
