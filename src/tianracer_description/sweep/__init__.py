"""Parameter sweeps of the race car: many scenarios (a track, a seed, the car's top speed, its steering
controllers' gains, follow the gap's speeds), each driven by follow the gap in a RaceEnv of its own,
one result row per scenario, run in this process or as Ray tasks on a cluster. Its modules:
scenarios (what a scenario is, running one, scenario sets), cluster (running a sweep, Ray), results
(the results file, the summary and its plot) and cli (the command line); their public names are
imported here.

    /usr/bin/python3 -m tianracer_description.sweep --grid max_speed=2,3 --grid seed=0,1,2 --local --out r.csv
    /usr/bin/python3 -m tianracer_description.sweep --random 200 --seed 1 --range max_speed=1.5,4 \\
        --address 127.0.0.1:6379 --out r.csv --plot r.png

A scenario is a plain dict of SCENARIO_FIELDS (missing ones at default_scenario()'s values);
run_scenario(scenario) drives it and returns a flat row: the scenario's fields and RESULT_FIELDS. It
never raises: what goes wrong in a scenario is in the row's `error`, with its seed, and the sweep goes
on. The plant is deterministic, so a scenario's row is the same wherever it runs (apart from
wall_seconds): in-process, on a local Ray or on a cluster's worker.

Rows are written as the scenarios finish (a CSV flushed row by row; .parquet, with pyarrow, at the
end), with a progress bar on stderr and a summary on stdout at the end.

Ray's workers must import this package: the driver hands them its ROS workspace's environment
(worker_environment(): PYTHONPATH, ROS_PACKAGE_PATH, ...) as the job's runtime_env, so a cluster
started by `ray start` in a shell without the workspace sourced runs the sweep too; on several
machines the workspace must be at the same path on each. On one machine a head started with
RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER=0 listens on loopback only, and a driver must have the variable as
well (else it looks for the head at the machine's network address and waits there): connect_ray
sets it for loopback addresses. A head that runs with token authentication (`ray start` turns it on
when it finds ~/.ray/auth_token, which a local ray.init() writes) takes a driver only with
RAY_AUTH_MODE=token and the token in its environment.
"""
from tianracer_description.sweep.scenarios import (  # noqa: F401
    ANSI_ESCAPE, FIELD_TYPES, RANDOM_RANGES, RESULT_FIELDS, RESULT_TYPES, SCENARIO_FIELDS, complete,
    controllers_with_steering_gains, default_scenario, drive, failed_row, failure, grid, random_scenarios,
    run_scenario, world_file)
from tianracer_description.sweep.results import (  # noqa: F401
    COLUMNS, INDEX_FIELD, ResultsFile, check_results_path, parse, plot, read_results, scenario_of, summary,
    varied_fields)
from tianracer_description.sweep.cluster import (  # noqa: F401
    CLUSTER_VARIABLE, LOOPBACK_HOSTS, WORKER_VARIABLES, check_listening, connect_ray, host_and_port, is_loopback,
    local_results, ray_results, run_sweep, worker_environment)
from tianracer_description.sweep.cli import argument_parser, field_values, main, scenarios_from  # noqa: F401
