# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The core's stderr lines reach the node's logger at their own level (issue 18 item 4), in
any order of levels (rclpy refuses a call site whose severity changes)."""

from types import SimpleNamespace

from armor_service.core_process import CoreProcess
from rclpy.logging import get_logger, LoggingSeverity


def test_each_line_is_logged_at_its_level_and_a_trace_at_the_last_one(capfd):
    logger = get_logger('core_log_levels_test')
    logger.set_level(LoggingSeverity.DEBUG)
    core = CoreProcess('unused.jar', {}, logger=logger)
    lines = [b'WARN journal: dropped a torn tail\n', b'INFO [c] r: QUERY IND CLASS [Room] -> 0\n',
             b'DEBUG reasoner: openllet: classified\n', b'ERROR internal error\n',
             b'\tat io.github.armor.core.ArmorCore.run(ArmorCore.java:1)\n',
             b'INFO restored reference \'r\'\n']
    core._forward_stderr(SimpleNamespace(stderr=lines))
    logged = [line for line in capfd.readouterr().err.splitlines()
              if 'core_log_levels_test' in line]
    levels = [line.split(']')[0].lstrip('[') for line in logged]
    assert levels == ['WARN', 'INFO', 'DEBUG', 'ERROR', 'ERROR', 'INFO'], logged
    assert logged[1].endswith('core: [c] r: QUERY IND CLASS [Room] -> 0'), logged
