# gazebo_dev: Gazebo's C++ API (find_package(gazebo)) in catkin's variables, so that a package
# that finds catkin with COMPONENTS gazebo_dev compiles and links against it through
# catkin_INCLUDE_DIRS and catkin_LIBRARIES, with Gazebo's compiler flags, as gazebo_ros_pkgs'
# gazebo_dev gives them.
find_package(gazebo REQUIRED)
message(STATUS "Gazebo version: ${GAZEBO_VERSION}")
set(gazebo_dev_INCLUDE_DIRS ${GAZEBO_INCLUDE_DIRS})
set(gazebo_dev_LIBRARY_DIRS ${GAZEBO_LIBRARY_DIRS})
set(gazebo_dev_LIBRARIES ${GAZEBO_LIBRARIES})
set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} ${GAZEBO_CXX_FLAGS}")
