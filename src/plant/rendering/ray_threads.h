// The threads that cast the sensors' rays: the calling thread and a pool of workers, one per
// hardware thread by default. A job's tasks are handed out one at a time, so results that each task
// computes alone do not depend on the number of threads.
#pragma once

#include <functional>

namespace bullet_plant
{
// Runs task(0) .. task(tasks - 1), each once, on the calling thread and the pool's workers; returns
// when all are done. One job at a time: concurrent callers take turns.
void parallelTasks(int tasks, const std::function<void(int)>& task);

// The number of threads that cast camera and lidar rays (the calling thread and n - 1 workers);
// by default (n <= 0) the machine's hardware threads. Results do not depend on it.
void setRayThreads(int n);
int rayThreads();

}  // namespace bullet_plant
