// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.events;

import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Delivers the core's events to its listeners (socket connections, subscriptions) on a thread of
 * its own, so a directive only pays for putting its event in a queue.
 *
 * <p>Order: events are delivered in the order they were published, one at a time, to every
 * listener. The core publishes a reference's events while it holds that reference, so each
 * reference's events arrive in revision order. Threading: {@link #publish} and the listener
 * methods may be called from any thread; listeners run on the feed's thread and must not block
 * for long (a listener that throws is logged and keeps its place).
 */
public final class EventFeed implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(EventFeed.class);

    private final LinkedBlockingQueue<CoreEvent> queue = new LinkedBlockingQueue<>();
    private final CopyOnWriteArrayList<Consumer<CoreEvent>> listeners = new CopyOnWriteArrayList<>();
    private Thread dispatcher;
    private volatile boolean closed;

    /** Queues an event for every listener; with no listener it is not kept (nobody could ask for it later). */
    public void publish(CoreEvent event) {
        if (!listeners.isEmpty() && !closed) {
            queue.add(event);
        }
    }

    /** Delivers every event published from now on to {@code listener}. */
    public synchronized void addListener(Consumer<CoreEvent> listener) {
        listeners.add(listener);
        if (dispatcher == null && !closed) {
            dispatcher = new Thread(this::deliver, "armor-events");
            dispatcher.setDaemon(true);
            dispatcher.start();
        }
    }

    public void removeListener(Consumer<CoreEvent> listener) {
        listeners.remove(listener);
    }

    /** Events published but not yet delivered (for tests and measurements). */
    public int backlog() {
        return queue.size();
    }

    private void deliver() {
        while (!closed) {
            CoreEvent event;
            try {
                event = queue.take();
            } catch (InterruptedException e) {
                return;
            }
            for (Consumer<CoreEvent> listener : listeners) {
                try {
                    listener.accept(event);
                } catch (RuntimeException e) {
                    LOG.warn("an event listener failed on an event of '{}': {}", event.reference(), e.toString());
                }
            }
        }
    }

    /** Stops delivering; events still queued are dropped. */
    @Override
    public synchronized void close() {
        closed = true;
        if (dispatcher != null) {
            dispatcher.interrupt();
        }
        queue.clear();
    }
}
