"""Python side of the Tianracer simulation: helpers the ROS scripts and tests import."""
