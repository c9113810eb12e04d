// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import io.github.armor.core.api.CoreConfig;
import java.io.InputStream;
import java.io.StringReader;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import org.xml.sax.InputSource;

/**
 * Run in a JVM of its own by {@link NetworkGuardTest} (the guard is process-wide): installs the
 * guard as the core does with web loading off, then tries every way out; prints one line each.
 */
public final class NetworkGuardProbe {
    private NetworkGuardProbe() {}

    public static void main(String[] args) throws Exception {
        NetworkGuard.install(CoreConfig.defaults());
        String server = "127.0.0.1:" + args[0];
        for (String address : List.of("http://" + server + "/a.owl", "https://" + server + "/a.owl",
                "ftp://" + server + "/a.owl", "jar:http://" + server + "/a.jar!/a.owl")) {
            try (InputStream in = new URL(address).openStream()) {
                System.out.println("OPENED " + address);
            } catch (Exception e) {
                System.out.println("refused " + address);
            }
        }
        String xml = "<?xml version=\"1.0\"?><!DOCTYPE a [<!ENTITY e SYSTEM \"http://" + server + "/e\">]><a>&e;</a>";
        try {
            DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new InputSource(new StringReader(xml)));
            System.out.println("OPENED external entity");
        } catch (Exception e) {
            System.out.println("refused external entity");
        }
        Path local = Files.writeString(Files.createTempFile("guard", ".txt"), "local");
        try (InputStream in = local.toUri().toURL().openStream()) {
            System.out.println(new String(in.readAllBytes()).equals("local") ? "read local file" : "WRONG local file");
        } finally {
            Files.delete(local);
        }
    }
}
