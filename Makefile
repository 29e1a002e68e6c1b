# Entry points of the Tianracer simulation. See README.md.
#   make sim    install what is missing, build, start the simulation and its browser viewer (GUI=false: headless)
#   make test   install what is missing, build, run the whole test suite
#   make test-quick  the same without the tests marked slow (docs/tests.md)
#   make bench  build, time the plant against MuJoCo and PyBullet (prints figures)
SHELL := /bin/bash
.DEFAULT_GOAL := help

# Debian's interpreter: rospy and the other ROS 1 Python packages live there, not in the first
# python3 on PATH.
PYTHON := /usr/bin/python3
# The catkin workspace lives in this ignored folder; its src/ links this package and compat/*.
WS := .ws
COMPAT_PACKAGES := $(notdir $(wildcard compat/*))
PACKAGE_ITEMS := $(filter-out compat,$(wildcard *))
# Everything ROS runs on loopback only.
ROS_ENV := source $(WS)/devel/setup.bash && export ROS_IP=127.0.0.1 && unset ROS_HOSTNAME &&
PYTEST_ARGS ?=
# The suite runs on pytest-xdist's workers, one per core, a test module to a worker (its module-scoped
# fixtures built once); the tests marked serial run alone after the rest (test/conftest.py).
# PYTEST_WORKERS=0: one process, as plain pytest.
PYTEST_WORKERS ?= auto
PYTEST := $(PYTHON) -m pytest -n $(PYTEST_WORKERS) --dist loadscope
# catkin_make's arguments, the same for every target so that none reconfigures the build; the
# install space is $(WS)/install unless PREFIX names another (make install PREFIX=/opt/tianracer).
PREFIX ?=
CATKIN_ARGS = -DPYTHON_EXECUTABLE=$(PYTHON) -DCMAKE_BUILD_TYPE=Release $(if $(PREFIX),-DCMAKE_INSTALL_PREFIX=$(abspath $(PREFIX))) \
	-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache
# ccache (tools/setup.sh installs it): a second clone, or a build after `make clean`, compiles only
# what changed. Paths under the clone are taken relative to it (CCACHE_BASEDIR), so that clones in
# other folders share the cache; the precompiled headers are cached too (the sloppiness they need).
export CCACHE_BASEDIR := $(CURDIR)
export CCACHE_SLOPPINESS := pch_defines,time_macros,include_file_mtime,include_file_ctime
# make sim: the browser viewer in gzclient's place (the tutorial's default), or false for headless.
GUI ?= true

.PHONY: help setup build install test test-quick sim demo bench bench-ros bench-drive bench-fleet bench-viewer bench-racing bench-meshes bench-lights figures step-cost soak clean

help:
	@echo "make sim    install what is missing, build, start the simulation; open the address it prints first (GUI=false: headless)"
	@echo "make test   install what is missing, build, run the whole test suite (PYTEST_ARGS=...)"
	@echo "make test-quick  build, the test suite without the tests marked slow (PYTEST_ARGS=...)"
	@echo "make demo   build, drive a figure-eight headless, print the figures, write figure_eight.png"
	@echo "make setup  install what is missing (apt and pip); quiet when nothing is"
	@echo "make build  build the catkin workspace in $(WS)/"
	@echo "make bench  build, time the plant against MuJoCo and PyBullet (installs them from PyPI if missing)"
	@echo "make bench-ros  build, time the ROS node: launch to running, real time factor, CPU, fastest"
	@echo "make bench-drive  build, the CPU a turtlebot3-like robot (diff drive, 360-ray lidar, IMU) costs the node"
	@echo "make bench-fleet  build, a fleet of 1 to 100 turtlebot3-like robots through ROS: RTF, plant CPU, physics-only cost"
	@echo "make bench-viewer  build, the plant's CPU with a browser page open and the page's frame rate"
	@echo "make bench-racing  build, env steps a second of the Gymnasium environments (single, vector on 1 and 2 threads)"
	@echo "make figures  build, print what the plant's acceptance tests measure (settling times, drift, radius)"
	@echo "make step-cost  build, count instructions per physics step (callgrind) and print a trajectory digest"
	@echo "make bench-meshes  build, the cost of a race track made of meshes (instructions per step, lidar rays/s)"
	@echo "make bench-lights  build, instructions a 640 x 480 camera frame costs lit by six lamps, and by the sun alone"
	@echo "make soak   build, drive SOAK_MINUTES (default 10) at full speed with every sensor on: RSS growth, non-finite states"
	@echo "make install  build, install every package (this one and compat/'s) into $(WS)/install (PREFIX=...: elsewhere)"
	@echo "make clean  remove $(WS)/"

setup:
	@bash tools/setup.sh

build: setup
	@# The package is linked item by item, leaving out compat/ and $(WS)/ itself: a link to the whole
	@# folder would make a loop that rosrun's `find -L` walks into.
	@[ ! -L $(WS)/src/tianracer_description ] || rm $(WS)/src/tianracer_description
	@mkdir -p $(WS)/src/tianracer_description
	@for item in $(filter-out package.xml,$(PACKAGE_ITEMS)); do ln -sfn ../../../$$item $(WS)/src/tianracer_description/$$item; done
	@# package.xml is a copy: catkin installs it as it finds it, and a link would be installed as a link.
	@rm -f $(WS)/src/tianracer_description/package.xml && cp package.xml $(WS)/src/tianracer_description/
	@for pkg in $(COMPAT_PACKAGES); do ln -sfn ../../compat/$$pkg $(WS)/src/$$pkg; done
	@find $(WS)/src $(WS)/src/tianracer_description -maxdepth 1 -xtype l -delete
	@cd $(WS) && catkin_make $(CATKIN_ARGS) all tests \
		> build.log 2>&1 || { tail -n 60 build.log; echo "make build: catkin_make failed; full log in $(WS)/build.log"; exit 1; }
	@# The browser viewer's page: three.js from the npm registry (web/package-lock.json), bundled by
	@# esbuild into web/dist/viewer.js; the modules stay in $(WS)/web, out of the package's tree.
	@# Packages already in npm's cache are taken from it (--prefer-offline: a fresh clone needs no
	@# download), and a download that stalls is retried after a minute rather than npm's five.
	@mkdir -p $(WS)/web
	@cmp -s web/package-lock.json $(WS)/web/package-lock.json && [ -d $(WS)/web/node_modules ] || { \
		cp web/package.json web/package-lock.json $(WS)/web/ && \
		(cd $(WS)/web && npm ci --prefer-offline --fetch-timeout=60000 --fetch-retries=4 --no-audit --no-fund \
			--loglevel=error) > $(WS)/web/npm.log 2>&1 || \
		{ cat $(WS)/web/npm.log; rm -f $(WS)/web/package-lock.json; echo "make build: npm ci failed"; exit 1; }; }
	@NODE_PATH=$(WS)/web/node_modules $(WS)/web/node_modules/.bin/esbuild web/src/viewer.js --bundle --minify \
		--format=iife --outfile=web/dist/viewer.js --log-level=warning
	@echo "built $(WS): source $(WS)/devel/setup.bash"

# The install space a user's workspace extends (README, "Your robot on the plant").
install: build
	@cd $(WS) && catkin_make $(CATKIN_ARGS) install > install.log 2>&1 || { tail -n 40 install.log; \
		echo "make install: catkin_make install failed; full log in $(WS)/install.log"; exit 1; }
	@echo "installed: source $$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' $(WS)/build/CMakeCache.txt)/setup.bash"

test: build
	@# /usr/bin first: rostest's own nodes (hztest) start with `/usr/bin/env python3`.
	@$(ROS_ENV) export PATH=/usr/bin:$$PATH && $(PYTEST) $(PYTEST_ARGS)

# The tests marked slow (pytest.ini) left out: the loop while working; `make test` before a commit.
test-quick: build
	@$(ROS_ENV) export PATH=/usr/bin:$$PATH && $(PYTEST) -m "not slow" $(PYTEST_ARGS)

sim: build
	@$(ROS_ENV) GUI=$(GUI) bash tools/sim.sh

# The peers come from PyPI for $(PYTHON), like xacro in tools/setup.sh; only the benchmark needs them.
bench: build
	@$(PYTHON) -c 'import mujoco, pybullet' 2>/dev/null || { echo "bench: installing mujoco and pybullet from PyPI for $(PYTHON)"; \
		$$([ "$$(id -u)" -eq 0 ] || echo sudo) $(PYTHON) -m pip install -q --root-user-action=ignore --break-system-packages mujoco pybullet; }
	@$(ROS_ENV) $(PYTHON) bench/plant_vs_peers.py
	@$(ROS_ENV) $(PYTHON) bench/sensor_bench.py
	@$(ROS_ENV) $(PYTHON) bench/box_pile_vs_mujoco.py
	@$(ROS_ENV) export PATH=/usr/bin:$$PATH && $(PYTHON) bench/house_bench.py

demo: build
	@$(ROS_ENV) $(PYTHON) tools/demo.py

bench-ros: build
	@$(ROS_ENV) $(PYTHON) bench/ros_plant_bench.py

# A turtlebot3-like robot (diff drive plugin, 360-ray lidar at 5 Hz, IMU) through the node: its CPU.
bench-drive: build
	@$(ROS_ENV) $(PYTHON) bench/diff_drive_cost.py

# A fleet of turtlebot3-like robots in their namespaces through ROS (issue 56's measure): FLEET_SIZES=1,10 to choose.
bench-fleet: build
	@$(ROS_ENV) $(PYTHON) bench/fleet_cost.py

# The browser viewer: the plant's CPU with a page open, the page's frames a second in headless chromium.
bench-viewer: build
	@$(ROS_ENV) export PATH=/usr/bin:$$PATH && $(PYTHON) bench/viewer_bench.py

# The Gymnasium environments: env steps a second, single and vector, with the 1081-ray lidar.
bench-racing: build
	@$(ROS_ENV) $(PYTHON) bench/racing_bench.py

figures: build
	@$(ROS_ENV) $(PYTHON) bench/plant_figures.py

# Instructions per step under callgrind (load-independent) and a digest that a pure refactoring keeps.
step-cost: build
	@command -v valgrind >/dev/null || { echo "step-cost: installing valgrind"; $$([ "$$(id -u)" -eq 0 ] || echo sudo) apt-get install -y -qq valgrind; }
	@$(ROS_ENV) $(PYTHON) bench/step_cost.py

bench-meshes: build
	@command -v valgrind >/dev/null || { echo "bench-meshes: installing valgrind"; $$([ "$$(id -u)" -eq 0 ] || echo sudo) apt-get install -y -qq valgrind; }
	@$(ROS_ENV) $(PYTHON) bench/mesh_cost.py

bench-lights: build
	@command -v valgrind >/dev/null || { echo "bench-lights: installing valgrind"; $$([ "$$(id -u)" -eq 0 ] || echo sudo) apt-get install -y -qq valgrind; }
	@$(ROS_ENV) $(PYTHON) bench/light_cost.py

# Not part of `make test`: minutes long by design.
soak: build
	@$(ROS_ENV) $(PYTHON) bench/soak.py

clean:
	rm -rf $(WS)
