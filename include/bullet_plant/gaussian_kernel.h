// gazebo_plugins' GaussianKernel, the noise its ROS plugins add by hand (gazebo_ros_range,
// block_laser, ft_sensor; velodyne_simulator's too): Box-Muller from one uniform pair per draw, the
// cosine half kept. Upstream draws from the process-wide rand(); here each plugin has its own
// rand_r state seeded with 0, so a plugin's noise is the same sequence on every run whatever else
// draws.
#pragma once

#include <cmath>
#include <cstdlib>

namespace bullet_plant
{
class GaussianKernel
{
public:
  double operator()(double mu, double sigma)
  {
    if (sigma == 0.0)
      return mu;
    const double u = double(rand_r(&seed_)) / double(RAND_MAX), v = double(rand_r(&seed_)) / double(RAND_MAX);
    return sigma * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v) + mu;
  }

private:
  unsigned int seed_ = 0;
};

}  // namespace bullet_plant
