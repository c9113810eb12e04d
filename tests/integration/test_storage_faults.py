# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""No acknowledged change is lost whatever the disk does: a real full filesystem (a 4 MiB tmpfs
this test mounts) and an ext4 image that turns read-only under the node.

The campaigns that fail every I/O call in turn are JUnit tests (StorageFaultsTest);
`fault_injection.py --storage` runs them longer and prints their figures.
"""

from fault_injection import FilesystemFaults
import pytest

pytestmark = pytest.mark.runs_for_minutes(2)


def test_full_disk_refuses_with_225_and_takes_changes_again_when_space_returns(tmp_path):
    faults = FilesystemFaults(tmp_path)
    try:
        audit = faults.full_disk(changes=40)
    finally:
        faults.close()
    print(audit.summary())
    assert audit.refused > 0 and audit.acknowledged > 0, audit.summary()
    assert audit.other_codes == [], audit.summary()
    assert audit.memory_differs == 0, audit.summary()
    assert audit.refusal_reported, audit.summary()
    assert audit.recovery_s is not None and audit.recovery_s < 5.0, audit.summary()
    assert audit.lost == 0 and audit.refused_present == 0, audit.summary()
    assert audit.damage_after_restart == [], audit.summary()


def test_filesystem_turning_read_only_refuses_with_225_and_loses_nothing(tmp_path):
    faults = FilesystemFaults(tmp_path)
    try:
        audit = faults.read_only(changes=6)
    finally:
        faults.close()
    print(audit.summary())
    assert audit.acknowledged == 6 and audit.refused == 6, audit.summary()
    assert audit.other_codes == [] and audit.memory_differs == 0, audit.summary()
    assert audit.lost == 0 and audit.refused_present == 0, audit.summary()
