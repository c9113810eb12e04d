# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The real core process, without ROS: its catalogue over the socket, and its settings checked."""

import os

from armor_contract import catalogue
from armor_service.core_process import CoreProcess, CoreUnavailable
import pytest

# install/setup.bash exports it; make test sources that.
JAR = os.environ['ARMOR_CORE_JAR']


def test_a_running_core_answers_its_catalogue_over_the_socket(tmp_path):
    core = CoreProcess(JAR, {'allowed_dirs': [str(tmp_path)]}, start_timeout_s=60)
    core.start()
    try:
        answered = catalogue.parse(core.catalogue(timeout_s=30))
    finally:
        core.stop()
    assert answered == catalogue.load()


def test_a_misspelt_setting_stops_the_core_instead_of_taking_a_default(tmp_path):
    core = CoreProcess(JAR, {'lock_wait': 5}, start_timeout_s=60)
    with pytest.raises(CoreUnavailable, match="unknown setting 'lock_wait'"):
        core.start()
    core.stop()
