// The threads that cast the sensors' rays: a TBB arena (oneTBB), or, for a world stepped on a TBB
// thread (bullet_plant.CarBatch steps worlds side by side), the arena that thread works in: the
// rays are one more nested loop of the worlds', sharing their threads by work stealing instead of
// queueing for threads of their own. A job's tasks are handed out one at a time,
// so results that each task computes alone do not depend on the number of threads.
#pragma once

#include <functional>

namespace bullet_plant
{
// Runs task(0) .. task(tasks - 1), each once, on the calling thread and the arena's; returns when
// all are done. Concurrent callers each get all their tasks run, on the threads they share.
void parallelTasks(int tasks, const std::function<void(int)>& task);

// The number of threads that cast lidar rays (the calling thread and n - 1 of TBB's); by default
// (n <= 0) the hardware threads this process may run on. Results do not depend on it. Set it
// between jobs, not during one.
void setRayThreads(int n);
int rayThreads();

}  // namespace bullet_plant
