from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(
    packages=['tianracer_description', 'tianracer_description.racing', 'tianracer_description.sweep'],
    package_dir={'': 'src'},
))
