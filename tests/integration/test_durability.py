# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""No acknowledged change is lost when the core or the node is killed: the kill campaign, short.

The full run is `fault_injection.py --kills 100 --target core`. A misbehaving disk is
test_storage_faults.py, damage found at restore test_state_damage.py, a stepping wall clock
test_clock_jumps.py.
"""

from fault_injection import Campaign
import pytest

pytestmark = pytest.mark.runs_for_minutes(2)


@pytest.mark.parametrize('target', ['core', 'node'])
def test_sigkill_loses_no_acknowledged_change(tmp_path, target):
    campaign = Campaign(tmp_path, target, seed=7)
    try:
        audit = campaign.run(kills=3)
    finally:
        campaign.close()
    assert audit.kills == 3
    assert audit.acknowledged_singles > 10 and audit.acknowledged_lists > 2, audit.summary()
    assert audit.lost == 0, audit.summary()
    assert audit.half_applied_lists == 0, audit.summary()
    assert audit.failed_list_leaks == 0, audit.summary()
