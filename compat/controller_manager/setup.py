from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(
    packages=['controller_manager', 'controller_manager_calls'],
    package_dir={'': 'src'},
))
