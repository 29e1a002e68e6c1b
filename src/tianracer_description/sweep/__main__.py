"""`/usr/bin/python3 -m tianracer_description.sweep`: the sweep's command line (cli.main). Ray's
workers import run_scenario from tianracer_description.sweep.scenarios by its name, never from here."""
import sys

from tianracer_description.sweep.cli import main

sys.exit(main())
