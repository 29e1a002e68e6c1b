#include "rendering/ray_threads.h"

#include <memory>
#include <mutex>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

namespace bullet_plant
{
namespace
{
std::mutex arena_mutex;  // guards the arena's making and replacement
std::unique_ptr<tbb::task_arena> arena;
int requested_threads = 0;  // 0: TBB's default, the hardware threads this process may run on

tbb::task_arena& rayArena()
{
  if (!arena)
  {
    arena.reset(new tbb::task_arena(requested_threads > 0 ? requested_threads : tbb::task_arena::automatic));
    arena->initialize();
  }
  return *arena;
}

}  // namespace

void parallelTasks(int tasks, const std::function<void(int)>& task)
{
  tbb::task_arena* threads;
  {
    std::lock_guard<std::mutex> lock(arena_mutex);
    threads = &rayArena();
  }
  if (tasks <= 1 || threads->max_concurrency() == 1)
  {
    for (int i = 0; i < tasks; ++i)
      task(i);
    return;
  }
  // One task at a time to each thread (a task is a packet of rays), from TBB's work stealing.
  const auto run = [&] { tbb::parallel_for(0, tasks, 1, [&](int i) { task(i); }, tbb::simple_partitioner()); };
  if (tbb::this_task_arena::current_thread_index() != tbb::task_arena::not_initialized)
    run();  // called on a TBB thread (worlds stepped side by side): nested, on the threads of its arena
  else
    threads->execute(run);
}

void setRayThreads(int n)
{
  std::lock_guard<std::mutex> lock(arena_mutex);
  requested_threads = n;
  arena.reset();
}

int rayThreads()
{
  std::lock_guard<std::mutex> lock(arena_mutex);
  return rayArena().max_concurrency();
}

}  // namespace bullet_plant
