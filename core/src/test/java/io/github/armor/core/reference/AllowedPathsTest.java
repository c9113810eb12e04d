// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.github.armor.core.api.ArmorException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A path is confined by where it finally leads, links followed as the kernel follows them. */
class AllowedPathsTest {
    @TempDir
    Path allowed;
    @TempDir
    Path outside;

    @Test
    void linksAreFollowedToTheirFinalTargetEvenWhenItDoesNotExist() throws IOException {
        AllowedPaths paths = new AllowedPaths(List.of(allowed));
        Path real = allowed.toRealPath();
        Files.createSymbolicLink(allowed.resolve("dangling"), outside.resolve("new.log"));
        Files.createSymbolicLink(allowed.resolve("relative"), Path.of("sub", "..", "file.owl"));
        Files.createDirectories(allowed.resolve("sub"));
        Files.createSymbolicLink(allowed.resolve("up"), outside);
        assertEquals(Optional.empty(), paths.inside(allowed.resolve("dangling")));
        assertEquals(Optional.empty(), paths.inside(allowed.resolve("up/file.owl")));
        // ".." after a link climbs from the link's target, not from the link.
        assertEquals(Optional.empty(), paths.inside(allowed.resolve("up/../" + outside.getFileName() + "/x")));
        assertEquals(Optional.of(real.resolve("file.owl")), paths.inside(allowed.resolve("relative")));
        assertEquals(Optional.of(real.resolve("not/yet/there.owl")), paths.inside(allowed.resolve("not/yet/there.owl")));
        ArmorException refused = assertThrows(ArmorException.class, () -> paths.check(allowed + "/dangling"));
        assertEquals(213, refused.exitCode().code());
        assertEquals(213, assertThrows(ArmorException.class, () -> paths.check("/etc/passwd")).exitCode().code());
        assertEquals(213, assertThrows(ArmorException.class, () -> paths.check("a\0b")).exitCode().code());
    }
}
