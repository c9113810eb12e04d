// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import com.google.gson.JsonObject;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;

/**
 * The last scenes each reference was shown in this session, as answered (QUERY SIT RECENT: the
 * web view explains their recognitions from it). In memory only and bounded; a reference that
 * is dropped takes its list with it (keys are weak).
 */
final class RecentScenes {
    static final int KEPT = 20;

    private final Map<Object, Deque<JsonObject>> byReference = new WeakHashMap<>();

    synchronized void record(Object reference, JsonObject scene) {
        Deque<JsonObject> scenes = byReference.computeIfAbsent(reference, r -> new ArrayDeque<>());
        if (scenes.size() == KEPT) {
            scenes.removeFirst();
        }
        scenes.addLast(scene);
    }

    /** Newest first. */
    synchronized List<JsonObject> of(Object reference) {
        List<JsonObject> newestFirst = new ArrayList<>();
        Deque<JsonObject> scenes = byReference.get(reference);
        if (scenes != null) {
            for (Iterator<JsonObject> it = scenes.descendingIterator(); it.hasNext(); ) {
                newestFirst.add(it.next());
            }
        }
        return newestFirst;
    }
}
