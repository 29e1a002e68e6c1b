// common::Time: a time in seconds and nanoseconds, as Gazebo keeps simulated and wall time (sec and
// nsec of one sign, |nsec| < 1e9 after every operation), with its arithmetic and comparisons
// against other times and against seconds as a double.
#pragma once

#include <sys/time.h>

#include <cstdint>
#include <ctime>
#include <iostream>
#include <string>

#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE Time
{
public:
  Time() : sec(0), nsec(0) {}
  Time(const Time& time) = default;
  Time(const struct timeval& tv);
  Time(const struct timespec& tv);
  Time(int32_t sec, int32_t nsec);
  Time(double seconds);
  virtual ~Time() = default;

  static const Time Zero;
  static const int32_t nsInSec;
  static const int32_t nsInMs;

  // The wall clock now (CLOCK_REALTIME), kept in a value the reference stays valid for.
  static const Time& GetWallTime();
  static const std::string& GetWallTimeAsISOString();
  void SetToWallTime();

  void Set(int32_t sec, int32_t nsec);
  void Set(double seconds);
  double Double() const;
  float Float() const;

  static Time Sleep(const common::Time& time);
  static Time MSleep(unsigned int ms);
  static Time NSleep(unsigned int ns);
  static Time NSleep(Time time);

  Time& operator=(const Time& time) = default;
  Time& operator=(const struct timeval& tv);
  Time& operator=(const struct timespec& tv);

  Time operator+(const Time& time) const;
  const Time& operator+=(const Time& time);
  Time operator-(const Time& time) const;
  const Time& operator-=(const Time& time);
  Time operator*(const Time& time) const;
  const Time& operator*=(const Time& time);
  Time operator/(const Time& time) const;
  const Time& operator/=(const Time& time);

  Time operator+(const struct timeval& tv) const { return *this + Time(tv); }
  Time operator+(const struct timespec& tv) const { return *this + Time(tv); }
  const Time& operator+=(const struct timeval& tv) { return *this += Time(tv); }
  const Time& operator+=(const struct timespec& tv) { return *this += Time(tv); }
  Time operator-(const struct timeval& tv) const { return *this - Time(tv); }
  Time operator-(const struct timespec& tv) const { return *this - Time(tv); }
  const Time& operator-=(const struct timeval& tv) { return *this -= Time(tv); }
  const Time& operator-=(const struct timespec& tv) { return *this -= Time(tv); }
  Time operator*(const struct timeval& tv) const { return *this * Time(tv); }
  Time operator*(const struct timespec& tv) const { return *this * Time(tv); }
  const Time& operator*=(const struct timeval& tv) { return *this *= Time(tv); }
  const Time& operator*=(const struct timespec& tv) { return *this *= Time(tv); }
  Time operator/(const struct timeval& tv) const { return *this / Time(tv); }
  Time operator/(const struct timespec& tv) const { return *this / Time(tv); }
  const Time& operator/=(const struct timeval& tv) { return *this /= Time(tv); }
  const Time& operator/=(const struct timespec& tv) { return *this /= Time(tv); }

  bool operator==(const Time& time) const { return sec == time.sec && nsec == time.nsec; }
  bool operator!=(const Time& time) const { return !(*this == time); }
  bool operator<(const Time& time) const { return sec < time.sec || (sec == time.sec && nsec < time.nsec); }
  bool operator<=(const Time& time) const { return !(time < *this); }
  bool operator>(const Time& time) const { return time < *this; }
  bool operator>=(const Time& time) const { return !(*this < time); }
  bool operator==(double time) const { return *this == Time(time); }
  bool operator!=(double time) const { return *this != Time(time); }
  bool operator<(double time) const { return *this < Time(time); }
  bool operator<=(double time) const { return *this <= Time(time); }
  bool operator>(double time) const { return *this > Time(time); }
  bool operator>=(double time) const { return *this >= Time(time); }
  bool operator==(const struct timeval& tv) const { return *this == Time(tv); }
  bool operator==(const struct timespec& tv) const { return *this == Time(tv); }
  bool operator!=(const struct timeval& tv) const { return *this != Time(tv); }
  bool operator!=(const struct timespec& tv) const { return *this != Time(tv); }
  bool operator<(const struct timeval& tv) const { return *this < Time(tv); }
  bool operator<(const struct timespec& tv) const { return *this < Time(tv); }
  bool operator<=(const struct timeval& tv) const { return *this <= Time(tv); }
  bool operator<=(const struct timespec& tv) const { return *this <= Time(tv); }
  bool operator>(const struct timeval& tv) const { return *this > Time(tv); }
  bool operator>(const struct timespec& tv) const { return *this > Time(tv); }
  bool operator>=(const struct timeval& tv) const { return *this >= Time(tv); }
  bool operator>=(const struct timespec& tv) const { return *this >= Time(tv); }

  // "sec nsec", as Gazebo writes and reads a Time.
  friend std::ostream& operator<<(std::ostream& out, const Time& time)
  {
    return out << time.sec << " " << time.nsec;
  }
  friend std::istream& operator>>(std::istream& in, Time& time)
  {
    in.setf(std::ios_base::skipws);
    in >> time.sec >> time.nsec;
    time.Correct();
    return in;
  }

  int32_t sec;
  int32_t nsec;

private:
  // sec and nsec of one sign, |nsec| under a second.
  void Correct();
};
}  // namespace common
}  // namespace gazebo
