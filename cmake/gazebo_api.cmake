# Gazebo 11's C++ API for users' plugins (include/gazebo-11/, src/gazebo/), and Gazebo's
# development files as users' packages find them: find_package(gazebo) (gazebo-config.cmake in
# share/gazebo/cmake of the devel and install spaces) and `pkg-config gazebo` (lib/pkgconfig);
# compat/gazebo_dev is catkin's gazebo_dev over them. Included by CMakeLists.txt.
find_package(sdformat12 REQUIRED)
find_package(ignition-math6 REQUIRED)
find_package(Boost REQUIRED)
find_package(Protobuf REQUIRED)
find_package(Threads REQUIRED)

set(GAZEBO_API_VERSION_FULL 11.15.1)  # include/gazebo-11/gazebo/gazebo_config.h says the same
set(GAZEBO_API_VERSION 11.15)
set(GAZEBO_API_MAJOR_VERSION 11)

# One of Gazebo's libraries or plugins: built from SOURCES into the devel space's lib folder (where
# GAZEBO_LIBRARY_DIRS and the plugin path find them), warnings on; VERSIONED: named as Gazebo 11's
# libraries are (libNAME.so.11).
function(gazebo_api_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "VERSIONED" "" "SOURCES")
  add_library(${name} SHARED ${arg_SOURCES})
  target_compile_options(${name} PRIVATE -Wall -Wextra)
  set_target_properties(${name} PROPERTIES
    LIBRARY_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION})
  if(arg_VERSIONED)
    set_target_properties(${name} PROPERTIES VERSION ${GAZEBO_API_VERSION_FULL} SOVERSION ${GAZEBO_API_MAJOR_VERSION})
  endif()
endfunction()

# Gazebo's common library: time, the console, events, plugin paths, animations.
gazebo_api_library(gazebo_common VERSIONED SOURCES
  src/gazebo/common/Animation.cc
  src/gazebo/common/Console.cc
  src/gazebo/common/Events.cc
  src/gazebo/common/Exception.cc
  src/gazebo/common/Image.cc
  src/gazebo/common/KeyFrame.cc
  src/gazebo/common/PID.cc
  src/gazebo/common/SphericalCoordinates.cc
  src/gazebo/common/SystemPaths.cc
  src/gazebo/common/Time.cc)
target_include_directories(gazebo_common PUBLIC
  include/gazebo-11 ${Boost_INCLUDE_DIRS})
target_link_libraries(gazebo_common PUBLIC sdformat12::sdformat12 ignition-math6::ignition-math6 ${CMAKE_DL_LIBS})
# Gazebo's physics classes for plugins (World, Model, Link, Joint) over the simulator's bridge
# (gazebo/physics/PlantBridge.hh), which the plant implements.
gazebo_api_library(gazebo_physics VERSIONED SOURCES
  src/gazebo/physics/Collision.cc
  src/gazebo/physics/Contact.cc
  src/gazebo/physics/Joint.cc
  src/gazebo/physics/JointController.cc
  src/gazebo/physics/Link.cc
  src/gazebo/physics/Model.cc
  src/gazebo/physics/MultiRayShape.cc
  src/gazebo/physics/PhysicsEngine.cc
  src/gazebo/physics/Shape.cc
  src/gazebo/physics/World.cc)
target_link_libraries(gazebo_physics PUBLIC gazebo_transport gazebo_msgs_protobuf gazebo_common)
# Gazebo's rendering library as camera sensors give it to plugins: their cameras, whose frames the
# simulator renders.
gazebo_api_library(gazebo_rendering VERSIONED SOURCES
  src/gazebo/rendering/Camera.cc
  src/gazebo/rendering/DepthCamera.cc
  src/gazebo/rendering/Distortion.cc)
target_link_libraries(gazebo_rendering PUBLIC gazebo_common)
# Gazebo's sensors library: the Sensor base class and the sensor types, over the simulator's sensors.
gazebo_api_library(gazebo_sensors VERSIONED SOURCES
  src/gazebo/sensors/AltimeterSensor.cc
  src/gazebo/sensors/CameraSensor.cc
  src/gazebo/sensors/ContactSensor.cc
  src/gazebo/sensors/DepthCameraSensor.cc
  src/gazebo/sensors/ForceTorqueSensor.cc
  src/gazebo/sensors/GpsSensor.cc
  src/gazebo/sensors/GpuRaySensor.cc
  src/gazebo/sensors/ImuSensor.cc
  src/gazebo/sensors/MagnetometerSensor.cc
  src/gazebo/sensors/MultiCameraSensor.cc
  src/gazebo/sensors/Noise.cc
  src/gazebo/sensors/LaserScanSensor.cc
  src/gazebo/sensors/RaySensor.cc
  src/gazebo/sensors/Sensor.cc
  src/gazebo/sensors/SensorManager.cc
  src/gazebo/sensors/SonarSensor.cc)
target_link_libraries(gazebo_sensors PUBLIC gazebo_rendering gazebo_physics gazebo_common)

# Gazebo's messages (gazebo::msgs, libgazebo_msgs): protobuf from the .proto files in
# src/gazebo/msgs/proto, each named FILE:MESSAGE (the message its file defines, whose handles
# MessageTypes.hh declares). Their headers are generated into the devel space's include folder.
set(GAZEBO_MSGS gz_string:GzString vector3d:Vector3d quaternion:Quaternion pose:Pose factory:Factory physics:Physics
  time:Time laserscan:LaserScan laserscan_stamped:LaserScanStamped world_stats:WorldStatistics imu:IMU
  wrench:Wrench wrench_stamped:WrenchStamped joint_wrench:JointWrench contact:Contact contacts:Contacts image:Image image_stamped:ImageStamped
  images_stamped:ImagesStamped altimeter:Altimeter magnetometer:Magnetometer gps:GPS sonar:Sonar pointcloud:PointCloud
  sonar_stamped:SonarStamped)
set(GAZEBO_MSGS_PROTO_DIR ${PROJECT_SOURCE_DIR}/src/gazebo/msgs/proto)
set(GAZEBO_MSGS_GENERATED ${CMAKE_CURRENT_BINARY_DIR}/gazebo_msgs)
set(GAZEBO_MSGS_INCLUDE_DIR ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION}/gazebo-11)
file(MAKE_DIRECTORY ${GAZEBO_MSGS_GENERATED} ${GAZEBO_MSGS_INCLUDE_DIR}/gazebo/msgs)
set(GAZEBO_MSGS_SOURCES)
set(GAZEBO_MSGS_HEADERS ${GAZEBO_MSGS_INCLUDE_DIR}/gazebo/msgs/MessageTypes.hh)
set(GAZEBO_MSGS_INCLUDES)
set(GAZEBO_MSGS_HANDLES)
set(GAZEBO_MSGS_CONST_HANDLES)
foreach(entry ${GAZEBO_MSGS})
  string(REPLACE ":" ";" entry ${entry})
  list(GET entry 0 file)
  list(GET entry 1 message)
  set(header ${GAZEBO_MSGS_INCLUDE_DIR}/gazebo/msgs/${file}.pb.h)
  add_custom_command(OUTPUT ${GAZEBO_MSGS_GENERATED}/${file}.pb.cc ${header}
    COMMAND protobuf::protoc --cpp_out=${GAZEBO_MSGS_GENERATED} -I${GAZEBO_MSGS_PROTO_DIR}
      ${GAZEBO_MSGS_PROTO_DIR}/${file}.proto
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${GAZEBO_MSGS_GENERATED}/${file}.pb.h ${header}
    DEPENDS ${GAZEBO_MSGS_PROTO_DIR}/${file}.proto protobuf::protoc
    COMMENT "gazebo::msgs: ${file}.proto")
  list(APPEND GAZEBO_MSGS_SOURCES ${GAZEBO_MSGS_GENERATED}/${file}.pb.cc)
  list(APPEND GAZEBO_MSGS_HEADERS ${header})
  string(APPEND GAZEBO_MSGS_INCLUDES "#include \"gazebo/msgs/${file}.pb.h\"\n")
  string(APPEND GAZEBO_MSGS_HANDLES "typedef boost::shared_ptr<gazebo::msgs::${message}> ${message}Ptr;\n")
  string(APPEND GAZEBO_MSGS_CONST_HANDLES
    "typedef const boost::shared_ptr<gazebo::msgs::${message} const> Const${message}Ptr;\n")
endforeach()
configure_file(cmake/MessageTypes.hh.in ${GAZEBO_MSGS_INCLUDE_DIR}/gazebo/msgs/MessageTypes.hh @ONLY)
# Named as Gazebo's library; the target's own name leaves `gazebo_msgs` to the ROS package.
gazebo_api_library(gazebo_msgs_protobuf VERSIONED SOURCES ${GAZEBO_MSGS_SOURCES} src/gazebo/msgs/msgs.cc)
target_include_directories(gazebo_msgs_protobuf PUBLIC include/gazebo-11 ${GAZEBO_MSGS_INCLUDE_DIR}
  ${GAZEBO_MSGS_GENERATED})
target_link_libraries(gazebo_msgs_protobuf PUBLIC gazebo_common protobuf::libprotobuf ignition-math6::ignition-math6)
set_target_properties(gazebo_msgs_protobuf PROPERTIES OUTPUT_NAME gazebo_msgs)
# protoc's code is not ours to warn about
target_compile_options(gazebo_msgs_protobuf PRIVATE -w)
install(FILES ${GAZEBO_MSGS_HEADERS} DESTINATION ${CATKIN_GLOBAL_INCLUDE_DESTINATION}/gazebo-11/gazebo/msgs)

# Gazebo's transport inside the process (gazebo/transport/TopicManager.hh): nodes, publishers,
# subscribers, with no master and no sockets.
gazebo_api_library(gazebo_transport VERSIONED SOURCES
  src/gazebo/transport/CallbackHelper.cc
  src/gazebo/transport/Node.cc
  src/gazebo/transport/Publisher.cc
  src/gazebo/transport/Subscriber.cc
  src/gazebo/transport/TopicManager.cc)
target_link_libraries(gazebo_transport PUBLIC gazebo_msgs_protobuf gazebo_common protobuf::libprotobuf Threads::Threads)

# Gazebo's own plugins that gazebo_ros_pkgs' plugins derive from and link by their bare names
# (gazebo_ros_elevator: ElevatorPlugin, gazebo_ros_harness: HarnessPlugin, gazebo_ros_wheel_slip:
# WheelSlipPlugin; gazebo_ros_laser, _range and _block_laser: RayPlugin; gazebo_ros_gpu_laser:
# GpuRayPlugin; gazebo_ros_bumper: ContactPlugin; gazebo_ros_camera and the cameras over it:
# CameraPlugin; gazebo_ros_depth_camera and gazebo_ros_openni_kinect: DepthCameraPlugin), in
# GAZEBO_LIBRARY_DIRS
# and GAZEBO_PLUGIN_PATH as Gazebo's.
set(GAZEBO_API_PLUGINS ElevatorPlugin HarnessPlugin WheelSlipPlugin RayPlugin GpuRayPlugin ImuSensorPlugin
  ContactPlugin CameraPlugin DepthCameraPlugin ForceTorquePlugin SonarPlugin)
foreach(plugin ${GAZEBO_API_PLUGINS})
  gazebo_api_library(${plugin} SOURCES src/gazebo/plugins/${plugin}.cc)
  target_link_libraries(${plugin} PUBLIC gazebo_sensors gazebo_physics gazebo_transport gazebo_msgs_protobuf
    gazebo_common)
endforeach()
install(TARGETS ${GAZEBO_API_PLUGINS} LIBRARY DESTINATION ${CATKIN_GLOBAL_LIB_DESTINATION})
# gazebo_ros_pkgs' plugins over them, as upstream builds them (ROS subscriptions on Gazebo's
# plugin): libgazebo_ros_elevator.so, libgazebo_ros_harness.so and libgazebo_ros_wheel_slip.so in the
# ROS lib folder, where the plant finds plugin files.
foreach(plugin_over_base gazebo_ros_elevator:ElevatorPlugin gazebo_ros_harness:HarnessPlugin
                         gazebo_ros_wheel_slip:WheelSlipPlugin)
  string(REPLACE ":" ";" plugin_over_base ${plugin_over_base})
  list(GET plugin_over_base 0 plugin)
  list(GET plugin_over_base 1 base)
  gazebo_api_library(${plugin} SOURCES src/gazebo/plugins/${plugin}.cpp)
  target_include_directories(${plugin} PRIVATE ${catkin_INCLUDE_DIRS})
  target_link_libraries(${plugin} ${base} ${catkin_LIBRARIES})
endforeach()
# gazebo_ros_wheel_slip's reconfigure header (cfg/WheelSlip.cfg).
target_include_directories(gazebo_ros_wheel_slip PRIVATE ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION})
add_dependencies(gazebo_ros_wheel_slip ${PROJECT_NAME}_gencfg)
install(TARGETS gazebo_ros_elevator gazebo_ros_harness gazebo_ros_wheel_slip
        LIBRARY DESTINATION ${CATKIN_GLOBAL_LIB_DESTINATION})

set(GAZEBO_API_TARGETS gazebo_sensors gazebo_rendering gazebo_physics gazebo_transport gazebo_msgs_protobuf gazebo_common)
set(GAZEBO_API_LIBRARIES gazebo_sensors gazebo_rendering gazebo_physics gazebo_transport gazebo_msgs gazebo_common)
list(TRANSFORM GAZEBO_API_LIBRARIES PREPEND -l OUTPUT_VARIABLE GAZEBO_API_PKG_LIBS)
list(JOIN GAZEBO_API_PKG_LIBS " " GAZEBO_API_PKG_LIBS)

install(TARGETS ${GAZEBO_API_TARGETS} LIBRARY DESTINATION ${CATKIN_GLOBAL_LIB_DESTINATION})
install(DIRECTORY include/gazebo-11/ DESTINATION ${CATKIN_GLOBAL_INCLUDE_DESTINATION}/gazebo-11)

# The config and pkg-config files, once for each space: its include folder and its lib folder.
foreach(space devel install)
  if(space STREQUAL devel)
    set(GAZEBO_API_PREFIX ${CATKIN_DEVEL_PREFIX})
    # the headers of the source tree and those the build generates (gazebo/msgs)
    set(GAZEBO_API_INCLUDE_DIR ${PROJECT_SOURCE_DIR}/include/gazebo-11)
    set(GAZEBO_API_INCLUDE_DIRS ${GAZEBO_API_INCLUDE_DIR} ${GAZEBO_MSGS_INCLUDE_DIR})
  else()
    set(GAZEBO_API_PREFIX ${CMAKE_INSTALL_PREFIX})
    set(GAZEBO_API_INCLUDE_DIR ${CMAKE_INSTALL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION}/gazebo-11)
    set(GAZEBO_API_INCLUDE_DIRS ${GAZEBO_API_INCLUDE_DIR})
  endif()
  set(GAZEBO_API_LIB_DIR ${GAZEBO_API_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION})
  list(TRANSFORM GAZEBO_API_INCLUDE_DIRS PREPEND -I OUTPUT_VARIABLE GAZEBO_API_PKG_CFLAGS)
  list(JOIN GAZEBO_API_PKG_CFLAGS " " GAZEBO_API_PKG_CFLAGS)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/gazebo_api_${space})
  configure_file(cmake/gazebo-config.cmake.in ${out}/gazebo-config.cmake @ONLY)
  configure_file(cmake/gazebo.pc.in ${out}/gazebo.pc @ONLY)
  include(CMakePackageConfigHelpers)
  write_basic_package_version_file(${out}/gazebo-config-version.cmake VERSION ${GAZEBO_API_VERSION_FULL}
    COMPATIBILITY AnyNewerVersion)
  if(space STREQUAL devel)
    file(COPY ${out}/gazebo-config.cmake ${out}/gazebo-config-version.cmake
      DESTINATION ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_SHARE_DESTINATION}/gazebo/cmake)
    file(COPY ${out}/gazebo.pc DESTINATION ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION}/pkgconfig)
  else()
    install(FILES ${out}/gazebo-config.cmake ${out}/gazebo-config-version.cmake
      DESTINATION ${CATKIN_GLOBAL_SHARE_DESTINATION}/gazebo/cmake)
    install(FILES ${out}/gazebo.pc DESTINATION ${CATKIN_GLOBAL_LIB_DESTINATION}/pkgconfig)
  endif()
endforeach()
