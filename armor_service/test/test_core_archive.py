# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The core's class data archive: used when it matches the jar, ignored in silence when not."""

import logging
import os
import pathlib
import shutil

from armor_service.core_process import CoreProcess

# install/setup.bash exports it; make test sources that.
JAR = pathlib.Path(os.environ['ARMOR_CORE_JAR'])
# Where the JVM says each class came from (-Xlog:class+load), one line per class.
MAIN_CLASS = 'io.github.armor.core.server.CoreMain'


def start_and_stop(jar: pathlib.Path, tmp_path: pathlib.Path, caplog, *jvm_options: str) -> str:
    """Start a core of jar until it answers; what the JVM said of the core's main class."""
    classes = tmp_path / 'classes.log'
    logger = logging.getLogger('armor_core_archive_test')
    core = CoreProcess(str(jar), {'allowed_dirs': [str(tmp_path)]}, start_timeout_s=120,
                       jvm_options=(f'-Xlog:class+load=info:file={classes}', *jvm_options),
                       logger=logger)
    with caplog.at_level(logging.DEBUG, logger=logger.name):
        core.start()
        try:
            assert core.catalogue(timeout_s=60)
        finally:
            core.stop()
    said = [record.getMessage() for record in caplog.records
            if 'archive' in record.getMessage() or 'cds' in record.getMessage()]
    assert said == [], 'the JVM said something about class sharing'
    return next(line for line in classes.read_text().splitlines() if f' {MAIN_CLASS} ' in line)


def test_the_installed_core_maps_its_classes_from_the_archive_set_up_made(tmp_path, caplog):
    assert JAR.with_suffix('.jsa').is_file(), 'tools/setup.sh made no archive beside the jar'
    assert 'source: shared objects file (top)' in start_and_stop(JAR, tmp_path, caplog)


def test_sharing_options_of_ones_own_replace_the_archive(tmp_path, caplog):
    assert start_and_stop(JAR, tmp_path, caplog, '-Xshare:off').endswith(f'source: file:{JAR}')


def test_an_archive_of_another_jar_or_no_archive_at_all_is_ignored_in_silence(tmp_path, caplog):
    # The archive beside a copy of the jar (the JVM checks path, size and time of each jar).
    rebuilt = tmp_path / 'core'
    rebuilt.mkdir()
    jar = rebuilt / JAR.name
    shutil.copyfile(JAR, jar)
    (rebuilt / 'lib').symlink_to(JAR.parent / 'lib')
    shutil.copyfile(JAR.with_suffix('.jsa'), jar.with_suffix('.jsa'))
    assert start_and_stop(jar, tmp_path, caplog).endswith(f'source: file:{jar}')
    # Not an archive at all (a write cut short), then none.
    jar.with_suffix('.jsa').write_bytes(b'not an archive')
    assert start_and_stop(jar, tmp_path, caplog).endswith(f'source: file:{jar}')
    jar.with_suffix('.jsa').unlink()
    assert start_and_stop(jar, tmp_path, caplog).endswith(f'source: file:{jar}')
