# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Exceptions raised by the client; the names are those of ROS 1 ARMOR's armor_api."""


class ArmorError(Exception):
    """Base of every error the ARMOR client raises."""


class ArmorServiceCallError(ArmorError):
    """The service answered, and the directive failed: carries ARMOR's exit code."""

    def __init__(self, exit_code: int, description: str, timeout: bool = False):
        super().__init__(f'{exit_code}: {description}')
        self.exit_code = exit_code
        self.description = description
        self.timeout = timeout


class ArmorServiceInternalError(ArmorError):
    """The service could not be reached or did not answer in time."""

    def __init__(self, description: str, exit_code: int = -1):
        super().__init__(description)
        self.exit_code = exit_code
        self.description = description
