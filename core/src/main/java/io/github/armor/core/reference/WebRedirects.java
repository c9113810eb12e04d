// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.io.IOException;
import java.net.HttpURLConnection;
import java.net.URISyntaxException;
import java.net.URL;
import java.util.Set;
import org.semanticweb.owlapi.model.IRI;

/**
 * Follows a web document's redirects before the OWL API fetches it (web loading on). The OWL
 * API follows a redirect to any scheme, so a server could send a LOAD WEB or an import to
 * {@code file:///etc/...}; here every hop must stay on http(s), and the OWL API is then told
 * not to follow redirects itself.
 */
final class WebRedirects {
    private static final int MAX_HOPS = 10;
    private static final int TIMEOUT_MS = 20_000;
    private static final Set<Integer> REDIRECTS = Set.of(301, 302, 303, 307, 308);
    // What the OWL API asks for by default: content negotiation may redirect by it.
    private static final String ACCEPT = "application/rdf+xml, application/xml; q=0.7, text/xml; q=0.6, "
            + "text/plain; q=0.1, */*; q=0.09";

    private WebRedirects() {}

    static boolean isWeb(IRI iri) {
        String scheme = iri.getScheme();
        return "http".equalsIgnoreCase(scheme) || "https".equalsIgnoreCase(scheme);
    }

    /** Where an http(s) IRI finally leads; 213 when a hop leaves http(s). */
    static IRI finalLocation(IRI iri) {
        try {
            URL url = iri.toURI().toURL();
            for (int hop = 0; hop <= MAX_HOPS; hop++) {
                HttpURLConnection connection = (HttpURLConnection) url.openConnection();
                connection.setInstanceFollowRedirects(false);
                connection.setConnectTimeout(TIMEOUT_MS);
                connection.setReadTimeout(TIMEOUT_MS);
                connection.setRequestProperty("Accept", ACCEPT);
                int status = connection.getResponseCode();
                String location = connection.getHeaderField("Location");
                connection.disconnect();
                if (!REDIRECTS.contains(status) || location == null) {
                    return IRI.create(url.toURI());
                }
                URL next = new URL(url, location);
                if (!next.getProtocol().equals("http") && !next.getProtocol().equals("https")) {
                    throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "<" + iri + "> redirects to <" + location
                            + ">, which is not a web address; only http(s) redirects are followed");
                }
                url = next;
            }
            throw new ArmorException(ExitCode.LOAD_FAILED, "<" + iri + "> redirects more than " + MAX_HOPS + " times");
        } catch (IOException | URISyntaxException | IllegalArgumentException | ClassCastException e) {
            // Unreachable or malformed: the OWL API's own fetch reports it with the document's name.
            return iri;
        }
    }
}
