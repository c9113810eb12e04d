// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.pipeline;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.Reference;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Who may change a reference now: the mount check, and the mount lease that lapses when its
 * holder has been silent for {@code mount_lease_s} (every directive a client sends renews it).
 */
public final class Admission {
    private static final Logger LOG = LoggerFactory.getLogger(Admission.class);

    private final CoreConfig config;
    private final Map<String, Long> lastHeardFrom = new ConcurrentHashMap<>();

    public Admission(CoreConfig config) {
        this.config = config;
    }

    /** Notes that the directive's client is alive (a standing query is not its client's activity). */
    void heard(Directive directive) {
        if (!directive.clientName().isEmpty()) {
            lastHeardFrom.put(directive.clientName(), System.nanoTime());
        }
    }

    /** Refuses a change while another client holds the reference's mount. */
    void check(Reference reference, Directive directive) {
        String holder = reference.mountedBy();
        if (!holder.isEmpty() && !holder.equals(directive.clientName())) {
            throw new ArmorException(ExitCode.REFERENCE_MOUNTED, "reference '" + reference.name()
                    + "' is mounted by client '" + holder + "'; " + directive.describe() + " refused, nothing changed");
        }
    }

    /** Releases the reference's mount when its holder has been silent longer than the lease. */
    void releaseExpired(Reference reference) {
        String holder = reference.mountedBy();
        if (holder.isEmpty() || config.mountLeaseS() <= 0) {
            return;
        }
        Long heard = lastHeardFrom.get(holder);
        if (heard == null || System.nanoTime() - heard > config.mountLeaseS() * 1_000_000_000L) {
            LOG.info("mount of '{}' by '{}' expired after {} s of silence", reference.name(), holder,
                    config.mountLeaseS());
            reference.setMountedBy("");
        }
    }

    /** How long the mount of {@code holder} has left before it expires, in ms; negative: mounts never expire. */
    public long leaseLeftMs(String holder) {
        if (config.mountLeaseS() <= 0) {
            return -1;
        }
        Long heard = lastHeardFrom.get(holder);
        long silentMs = heard == null ? Long.MAX_VALUE : (System.nanoTime() - heard) / 1_000_000;
        return Math.max(0, config.mountLeaseS() * 1000 - silentMs);
    }
}
