"""A video of an episode: pure pursuit lapping a map's track, seen from above (or from its chase
camera), recorded by Gymnasium's RecordVideo (MoviePy, which `make setup` installs), run with the
workspace sourced:

    /usr/bin/python3 examples/racing/record_video.py                  # videos/pure_pursuit-episode-0.mp4
    /usr/bin/python3 examples/racing/record_video.py --view chase --seconds 10
    /usr/bin/python3 examples/racing/record_video.py --scale 0.0125 --gif docs/images/top_down_peanut.gif

The environment steps every 40 ms (--control-period), so the video has 25 frames a second of
simulated time and plays at its pace. --gif also writes the first --gif-seconds of the episode as
an animated GIF (Pillow), every --gif-every'th frame: how docs/images/top_down_peanut.gif was made.
"""
import argparse
import os

import gymnasium
import numpy as np
from gymnasium.wrappers import RecordVideo

import tianracer_description.racing  # noqa: F401  registers the environments
from tianracer_description.racing.pure_pursuit import PurePursuit
from tianracer_description.tianracer import PEANUT_MAP


def record_episode(env, policy, seed, gif_frames=None):
    """Drives one episode of `policy` in `env` (RecordVideo records it); the frames for a GIF are
    appended to `gif_frames` where it is a list. Returns (laps, crashed, steps)."""
    observation, info = env.reset(seed=seed)
    steps = 0
    while True:
        if gif_frames is not None:
            gif_frames.append(env.render())
        observation, _, terminated, truncated, info = env.step(policy(observation))
        steps += 1
        if terminated or truncated:
            return info['laps'], bool(info['crashed']), steps


def write_gif(path, frames, period):
    """frames (H x W x 3, uint8) as an animated GIF looping forever, `period` seconds a frame; one
    palette for all (the views' few flat colours), so that frames differ only where things move."""
    from PIL import Image  # Debian's python3-pil
    images = [Image.fromarray(np.asarray(f, np.uint8)) for f in frames]
    palette = images[0].quantize(colors=64, method=Image.Quantize.MEDIANCUT)
    images = [image.quantize(palette=palette, dither=Image.Dither.NONE) for image in images]
    images[0].save(path, save_all=True, append_images=images[1:], duration=int(round(period * 1000)), loop=0,
                   optimize=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--map', default=PEANUT_MAP, help="a map_server YAML of f1tenth's (default: %(default)s)")
    parser.add_argument('--view', default='top_down', choices=['top_down', 'chase'], help='what the video shows')
    parser.add_argument('--seconds', type=float, default=20.0, help='of simulated time at most (default: 20)')
    parser.add_argument('--control-period', type=float, default=0.04, help='s a step and a frame (default: 0.04)')
    parser.add_argument('--scale', type=float, help='the top-down view\'s metres a pixel (default: 0.025)')
    parser.add_argument('--max-speed', type=float, default=2.0, help='m/s an action of 1 asks for')
    parser.add_argument('--folder', default='videos', help='where RecordVideo writes (default: %(default)s)')
    parser.add_argument('--gif', help='also write the start of the episode as an animated GIF here')
    parser.add_argument('--gif-seconds', type=float, default=8.0, help='of the episode the GIF shows')
    parser.add_argument('--gif-every', type=int, default=2, help='the GIF keeps every n-th frame (default: 2)')
    parser.add_argument('--seed', type=int, default=0)
    args = parser.parse_args()
    steps = int(round(args.seconds / args.control_period))
    env = gymnasium.make('Tianracer-Map-v0', map=args.map, render_mode='rgb_array', view=args.view,
                         top_down_scale=args.scale, control_period=args.control_period, max_speed=args.max_speed, observe_pose=True,
                         max_episode_steps=steps)
    env = RecordVideo(env, args.folder, name_prefix='pure_pursuit', episode_trigger=lambda episode: True)
    policy = PurePursuit.for_env(env)
    gif_frames = [] if args.gif else None
    laps, crashed, taken = record_episode(env, policy, args.seed, gif_frames)
    env.close()  # RecordVideo writes the video
    video = os.path.join(args.folder, 'pure_pursuit-episode-0.mp4')
    print('%.2f laps in %d steps (%s): %s, %.0f kB' % (laps, taken, 'touched a wall' if crashed else 'no wall touched',
                                                      video, os.path.getsize(video) / 1e3))
    if args.gif:
        kept = gif_frames[:int(round(args.gif_seconds / args.control_period)):args.gif_every]
        write_gif(args.gif, kept, args.control_period * args.gif_every)
        print('%s: %d frames, %.0f kB' % (args.gif, len(kept), os.path.getsize(args.gif) / 1e3))


if __name__ == '__main__':
    main()
