// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import io.github.armor.core.api.CoreConfig;
import java.io.IOException;
import java.net.URL;
import java.net.URLConnection;
import java.net.URLStreamHandler;
import java.util.Set;

/**
 * The process-wide backstop behind the core's own checks. Loading and SPARQL refuse remote
 * documents and endpoints themselves, with a clear code; this makes sure that nothing a library
 * opens on its own (an XML parser's external DTD, a redirect, a scheme nobody thought of)
 * reaches the network while web loading is off.
 */
final class NetworkGuard {
    // file: and jrt: cannot be replaced by a factory; jar: reads a local jar, and a remote one
    // through an inner URL that this guard refuses in turn.
    private static final Set<String> LOCAL_PROTOCOLS = Set.of("file", "jar", "jrt");

    private NetworkGuard() {}

    static void install(CoreConfig config) {
        // JAXP parsers fetch no external DTD, entity or schema over any protocol.
        System.setProperty("javax.xml.accessExternalDTD", "");
        System.setProperty("javax.xml.accessExternalSchema", "");
        if (!config.webLoading()) {
            URL.setURLStreamHandlerFactory(protocol -> LOCAL_PROTOCOLS.contains(protocol) ? null : new Refusing());
        }
    }

    /** Every connection fails before it is made. */
    private static final class Refusing extends URLStreamHandler {
        @Override
        protected URLConnection openConnection(URL url) throws IOException {
            throw new IOException("network access is off (node parameter web_loading): " + url);
        }

        @Override
        protected URLConnection openConnection(URL url, java.net.Proxy proxy) throws IOException {
            return openConnection(url);
        }
    }
}
