// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.SizeLimits;
import io.github.armor.core.command.Catalogue;
import io.github.armor.core.events.AnswerEvent;
import io.github.armor.core.events.ChangeEvent;
import io.github.armor.core.events.CoreEvent;
import io.github.armor.core.events.Subscriptions;
import io.github.armor.core.view.ReferenceViews;
import java.io.EOFException;
import java.io.IOException;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Serves {@link ArmorCore} on a Unix domain socket. Frames are a 4-byte big-endian length and a
 * UTF-8 JSON object. A request carries an {@code id} the response repeats, so one connection
 * carries many requests at once: each runs on a thread of its own (the one that read it) and
 * answers when done.
 *
 * <p>Requests: {@code {"id", "op": "directive", "directive": {...}}},
 * {@code {"id", "op": "list", "directives": [...]}}, {@code {"id", "op": "ping"}}, and the read-only
 * {@code {"id", "op": "catalogue"}}, answered {@code {"id", "catalogue": {...}}} (see {@link Catalogue}), and
 * the read-only {@code {"id", "op": "view", "view": {"name", ...}}} of the web page, answered
 * {@code {"id", "view": {...}}} (see {@link ReferenceViews}).
 *
 * <p>Events: the core also sends every connection frames nobody asked for, without an {@code id}
 * and with an {@code "event"} key: {@code "change"} for each acknowledged change of a reference
 * ({@link ChangeEvent}), in revision order per reference, and {@code "answer"} for what changed in
 * a subscription's answer ({@link AnswerEvent}).
 *
 * <p>Subscriptions ({@link Subscriptions}): {@code {"id", "op": "subscribe", "subscription": ID,
 * "directive": {...}[, "known": [...]]}} registers a standing query under the client's ID and is
 * answered {@code {"id", "response": {...}, "revision": n}}: the query's first answer (a failed
 * one registered nothing), whose "answer" event has already been sent. {@code {"id", "op":
 * "unsubscribe", "subscription": ID}} is answered {@code {"id", "unsubscribed": bool}};
 * {@code {"id", "op": "subscriptions"}} {@code {"id", "subscriptions": count}}. A connection's
 * subscriptions end when it closes.
 */
public final class CoreServer {
    private static final Logger LOG = LoggerFactory.getLogger(CoreServer.class);
    // Reasoners recurse deeply on real ontologies; a large stack turns many overflows into answers.
    private static final long WORKER_STACK_BYTES = 256L << 20;

    private final ArmorCore core;
    private final JsonObject catalogue;
    private final ReferenceViews views;
    private final ExecutorService workers = Executors.newCachedThreadPool(new WorkerThreads());

    public CoreServer(ArmorCore core, JsonObject catalogue) {
        this.core = core;
        this.catalogue = catalogue;
        this.views = core.views();
    }

    /** Binds the socket, then calls {@code onReady} and serves until the process ends. */
    public void serve(Path socketPath, Runnable onReady) throws IOException {
        Files.deleteIfExists(socketPath);
        try (ServerSocketChannel server = ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
            server.bind(UnixDomainSocketAddress.of(socketPath));
            onReady.run();
            while (true) {
                SocketChannel connection = server.accept();
                // A worker (its large stack): the thread that reads a request also answers it.
                workers.execute(() -> serveConnection(connection));
            }
        }
    }

    private void serveConnection(SocketChannel connection) {
        Connection served = new Connection(connection);
        core.events().addListener(served.pushEvent);
        readAndAnswer(served);
    }

    /** One client connection: its channel, the lock its frames are written under, its subscriptions. */
    private final class Connection {
        final SocketChannel channel;
        final Object writeLock = new Object();
        final Set<String> subscribed = ConcurrentHashMap.newKeySet();
        final Consumer<CoreEvent> pushEvent = this::push;

        Connection(SocketChannel channel) {
            this.channel = channel;
        }

        private void push(CoreEvent event) {
            byte[] frame = event.toJson().toString().getBytes(StandardCharsets.UTF_8);
            if (frame.length > SizeLimits.FRAME_BYTES) {
                LOG.warn("an event of {} bytes is larger than a frame ({}); not sent", frame.length,
                        SizeLimits.FRAME_BYTES);
                return;
            }
            try {
                write(frame);
            } catch (IOException e) {
                LOG.debug("could not send an event: {}", e.toString());
            }
        }

        void write(byte[] frame) throws IOException {
            synchronized (writeLock) {
                writeFrame(channel, frame);
            }
        }

        void close() {
            core.events().removeListener(pushEvent);
            subscribed.forEach(core.subscriptions()::unsubscribe);
            try {
                channel.close();
            } catch (IOException e) {
                LOG.debug("closing a connection: {}", e.toString());
            }
        }
    }

    /**
     * Reads the connection's next request, passes the reading of the one after to a worker, and
     * answers this one on the thread that read it. Requests still run side by side, but none
     * waits for a thread to be woken before it starts: on a busy machine each hand-off between
     * threads costs a wait for a core, paid by every directive.
     */
    private void readAndAnswer(Connection served) {
        JsonObject request;
        try {
            request = JsonParser.parseString(readFrame(served.channel)).getAsJsonObject();
        } catch (EOFException e) {
            LOG.debug("client disconnected");
            served.close();
            return;
        } catch (IOException | RuntimeException e) {
            LOG.warn("connection closed: {}", e.toString());
            served.close();
            return;
        }
        workers.execute(() -> readAndAnswer(served));
        byte[] reply = fitted(request, answer(request, served.subscribed));
        try {
            served.write(reply);
        } catch (IOException e) {
            LOG.warn("could not send a reply: {}", e.toString());
        }
    }

    private JsonObject answer(JsonObject request, Set<String> subscribed) {
        JsonObject reply = new JsonObject();
        reply.add("id", request.get("id"));
        String op = request.has("op") ? request.get("op").getAsString() : "";
        try {
            switch (op) {
                case "directive" -> reply.add("response",
                        WireCodec.response(core.execute(WireCodec.directive(request.getAsJsonObject("directive")))));
                case "list" -> reply.add("list",
                        WireCodec.listResponse(core.executeList(WireCodec.directives(request.getAsJsonArray("directives")))));
                case "ping" -> reply.addProperty("pong", true);
                case "catalogue" -> reply.add("catalogue", catalogue);
                case "view" -> reply.add("view", views.answer(request.getAsJsonObject("view")));
                case "subscribe" -> subscribe(request, reply, subscribed);
                case "unsubscribe" -> {
                    String subscription = request.get("subscription").getAsString();
                    subscribed.remove(subscription);
                    reply.addProperty("unsubscribed", core.subscriptions().unsubscribe(subscription));
                }
                case "subscriptions" -> reply.addProperty("subscriptions", core.subscriptions().count());
                default -> reply.addProperty("error", "unknown op '" + op + "'");
            }
        } catch (RuntimeException | LinkageError | StackOverflowError e) {
            // Whatever went wrong, the request is answered: a caller must never wait forever.
            LOG.error("request failed", e);
            reply.addProperty("error", "request failed in the core: " + e);
        }
        return reply;
    }

    /**
     * The reply as a frame's bytes; a reply larger than a frame (the node would drop the
     * connection, and with it the core) becomes its request's 221 instead. Lists never get here
     * ({@link SizeLimits#addAnswer}); one answer of a huge reference's query can.
     */
    private static byte[] fitted(JsonObject request, JsonObject reply) {
        byte[] bytes = reply.toString().getBytes(StandardCharsets.UTF_8);
        if (bytes.length <= SizeLimits.FRAME_BYTES) {
            return bytes;
        }
        ArmorException tooLarge = SizeLimits.tooLarge("the answer is " + SizeLimits.size(bytes.length)
                + " as a frame from the core to the node; the limit is " + SizeLimits.size(SizeLimits.FRAME_BYTES)
                + " (narrow the question)");
        JsonObject refused = new JsonObject();
        refused.add("id", request.get("id"));
        Response failure = Response.failure(tooLarge, false);
        if (reply.has("response")) {
            refused.add("response", WireCodec.response(failure));
        } else if (reply.has("list")) {
            int count = request.getAsJsonArray("directives").size();
            refused.add("list", WireCodec.listResponse(new ListResponse(false, false,
                    java.util.Collections.nCopies(count, failure))));
        } else {
            refused.addProperty("error", tooLarge.getMessage());
        }
        return refused.toString().getBytes(StandardCharsets.UTF_8);
    }

    private void subscribe(JsonObject request, JsonObject reply, Set<String> subscribed) {
        String id = request.get("subscription").getAsString();
        List<String> known = null;
        if (request.has("known") && request.get("known").isJsonArray()) {
            known = new ArrayList<>();
            for (var answer : request.getAsJsonArray("known")) {
                known.add(answer.getAsString());
            }
        }
        subscribed.add(id);
        Subscriptions.Evaluation first = core.subscriptions().subscribe(id,
                WireCodec.directive(request.getAsJsonObject("directive")), known);
        if (!first.response().success() || first.response().timeout()) {
            subscribed.remove(id);
        }
        reply.add("response", WireCodec.response(first.response()));
        reply.addProperty("revision", first.revision());
    }

    private static String readFrame(SocketChannel channel) throws IOException {
        ByteBuffer header = readFully(channel, 4);
        int length = header.getInt();
        if (length < 0 || length > SizeLimits.FRAME_BYTES) {
            throw new IOException("frame length " + length + " out of range");
        }
        return StandardCharsets.UTF_8.decode(readFully(channel, length)).toString();
    }

    private static ByteBuffer readFully(SocketChannel channel, int length) throws IOException {
        ByteBuffer buffer = ByteBuffer.allocate(length);
        while (buffer.hasRemaining()) {
            if (channel.read(buffer) < 0) {
                throw new EOFException();
            }
        }
        return buffer.flip();
    }

    private static void writeFrame(SocketChannel channel, byte[] payload) throws IOException {
        ByteBuffer frame = ByteBuffer.allocate(4 + payload.length).putInt(payload.length).put(payload).flip();
        while (frame.hasRemaining()) {
            channel.write(frame);
        }
    }

    private static final class WorkerThreads implements ThreadFactory {
        private final AtomicInteger count = new AtomicInteger();

        @Override
        public Thread newThread(Runnable work) {
            Thread thread = new Thread(null, work, "armor-worker-" + count.incrementAndGet(), WORKER_STACK_BYTES);
            thread.setDaemon(true);
            return thread;
        }
    }
}
