"""The viewer's camera overlays' JPEGs (tianracer_description.viewer.jpeg_of), without ROS running:
colour encodings as they are, depths as grey from near (dark) to far (light), nothing black."""
import io

import numpy as np
import pytest
from PIL import Image as PilImage
from sensor_msgs.msg import Image

from tianracer_description.viewer import jpeg_of


def image(encoding, pixels, bytes_per_pixel):
    m = Image(height=pixels.shape[0], width=pixels.shape[1], encoding=encoding)
    m.step = pixels.shape[1] * bytes_per_pixel + 4  # rows padded, as a driver may pad them
    rows = np.zeros((m.height, m.step), np.uint8)
    rows[:, :m.width * bytes_per_pixel] = np.frombuffer(pixels.tobytes(), np.uint8).reshape(m.height, -1)
    m.data = rows.tobytes()
    return m


def decoded(jpeg):
    return np.asarray(PilImage.open(io.BytesIO(jpeg)).convert('RGB'), dtype=float)


def halves():
    pixels = np.zeros((16, 32, 3), np.uint8)
    pixels[:, :16] = (200, 30, 30)
    pixels[:, 16:] = (30, 30, 200)
    return pixels


def test_rgb8_and_bgr8_come_out_in_their_colours():
    for encoding, pixels in (('rgb8', halves()), ('bgr8', halves()[:, :, ::-1])):
        out = decoded(jpeg_of(image(encoding, np.ascontiguousarray(pixels), 3)))
        assert out.shape == (16, 32, 3)
        assert np.abs(out[4:12, 2:12].mean(axis=(0, 1)) - (200, 30, 30)).max() < 8, encoding
        assert np.abs(out[4:12, 20:30].mean(axis=(0, 1)) - (30, 30, 200)).max() < 8, encoding


def test_a_depth_image_is_grey_from_near_dark_to_far_light_and_nothing_black():
    depth = np.full((16, 48), np.nan, np.float32)
    depth[:, 16:32] = 1.0
    depth[:, 32:] = 5.0
    out = decoded(jpeg_of(image('32FC1', depth, 4)))
    nothing, near, far = out[4:12, 2:12].mean(), out[4:12, 18:30].mean(), out[4:12, 34:46].mean()
    assert nothing < 10 and 45 < near < 65 and far > 245, (nothing, near, far)


def test_an_encoding_it_does_not_show_is_refused_by_name():
    with pytest.raises(ValueError, match='bayer_rggb8'):
        jpeg_of(image('bayer_rggb8', np.zeros((4, 4), np.uint8), 1))
