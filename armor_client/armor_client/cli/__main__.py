# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""`python -m armor_client.cli` runs the armor command (as the console script does)."""

import sys

from armor_client.cli import main

sys.exit(main())
