// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import java.util.Locale;

/**
 * What a command does to the core's state, which decides how the core runs it: the reference it
 * needs, whether another client's mount refuses it, whether it is journaled, whether it forgets
 * a reference's kept state. The core decides by kind, never by a command's name.
 */
public enum CommandKind {
    /** A question: on an existing reference, never refused under a mount, never journaled. */
    QUERY(Target.EXISTING, false, false, false),
    /** A change of the ontology: refused with 102 under another client's mount, journaled. */
    MANIPULATION(Target.EXISTING, true, true, true),
    /** Takes or releases the mount: journaled (a restarted core keeps the holder), no mount check. */
    MOUNTING(Target.EXISTING, false, true, false),
    /** Unloads the reference: its kept state is deleted too. */
    DROPPING(Target.EXISTING, false, false, false),
    /** Works on an existing reference without changing it (SAVE). */
    REFERENCE(Target.EXISTING, false, false, false),
    /** Creates the reference the directive names (LOAD, CREATE). */
    CREATING(Target.NEW, false, false, true),
    /** Needs no reference (GET ALL REFS, LOG). */
    GLOBAL(Target.NONE, false, false, false);

    /** What the reference name of a directive must name. */
    public enum Target {
        /** Works without a reference. */
        NONE,
        /** Creates the reference. */
        NEW,
        /** An existing reference. */
        EXISTING
    }

    private final Target target;
    private final boolean mountChecked;
    private final boolean journaled;
    private final boolean changesOntology;

    CommandKind(Target target, boolean mountChecked, boolean journaled, boolean changesOntology) {
        this.target = target;
        this.mountChecked = mountChecked;
        this.journaled = journaled;
        this.changesOntology = changesOntology;
    }

    public Target target() {
        return target;
    }

    /** Refused with 102 while another client holds the reference's mount; undone when its list fails. */
    public boolean mountChecked() {
        return mountChecked;
    }

    /** Its effect must survive a restart, so the core journals it before acknowledging. */
    public boolean journaled() {
        return journaled;
    }

    /** Whether it can change what the reference's ontology says. */
    public boolean changesOntology() {
        return changesOntology;
    }

    /** The name in the catalogue: {@code query}, {@code manipulation}, ... */
    public String catalogueName() {
        return name().toLowerCase(Locale.ROOT);
    }
}
