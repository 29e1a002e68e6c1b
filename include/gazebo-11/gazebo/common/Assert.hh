// GZ_ASSERT as Gazebo's: boost's assertion with a message (compiled out under NDEBUG).
#pragma once

#include <boost/assert.hpp>

#define GZ_ASSERT(_expr, _msg) BOOST_ASSERT_MSG(_expr, _msg)
