// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;

/**
 * The loaded references by name, and the client that made each (so that one client cannot fill
 * the core with references: node parameter references_per_client). Lookups are lock-free;
 * creations are serialised.
 */
public final class ReferenceRegistry {
    private final ConcurrentHashMap<String, Reference> references = new ConcurrentHashMap<>();
    // Reference -> the client_name of its LOAD or CREATE (references restored at start have none).
    private final Map<Reference, String> madeBy = new ConcurrentHashMap<>();

    public Reference get(String name) {
        Reference reference = references.get(name);
        if (reference == null) {
            throw new ArmorException(ExitCode.UNKNOWN_REFERENCE, "no reference named '" + name
                    + "' is loaded; loaded: " + names());
        }
        return reference;
    }

    public Optional<Reference> find(String name) {
        return Optional.ofNullable(references.get(name));
    }

    /**
     * The reference under {@code name}, created by {@code creation} for {@code client} if there is
     * none. An existing reference is reused only when it came from the same source (ARMOR's rule
     * for LOAD). 226, before any work, when the client already made {@code perClient} references
     * that are still loaded (0: no limit).
     */
    public synchronized Reference createOrReuse(String name, String source, String client, long perClient,
                                                Supplier<Reference> creation) {
        Reference existing = references.get(name);
        if (existing != null) {
            if (source != null && source.equals(existing.source())) {
                return existing;
            }
            throw new ArmorException(ExitCode.REFERENCE_EXISTS, "reference '" + name + "' is already loaded from "
                    + (existing.source() == null ? "CREATE" : "'" + existing.source() + "'") + "; DROP it first");
        }
        long made = madeBy.values().stream().filter(client::equals).count();
        if (perClient > 0 && made >= perClient) {
            throw new ArmorException(ExitCode.CLIENT_LIMIT, "client '" + client + "' has made " + made
                    + " references that are still loaded, the most one client may (node parameter"
                    + " references_per_client); DROP one first");
        }
        Reference created = creation.get();
        references.put(name, created);
        madeBy.put(created, client);
        return created;
    }

    /** Adds a reference recovered from the state directory. */
    public void register(Reference reference) {
        references.put(reference.name(), reference);
    }

    public void remove(Reference reference) {
        references.remove(reference.name(), reference);
        madeBy.remove(reference);
        reference.dispose();
    }

    public List<String> names() {
        return references.keySet().stream().sorted().toList();
    }
}
