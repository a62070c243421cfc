package carom.app;

import picocli.CommandLine.IVersionProvider;

/** {@code carom --version}: the jar's implementation version when packaged, else a development marker. */
final class VersionProvider implements IVersionProvider {
    @Override
    public String[] getVersion() {
        String v = Main.class.getPackage().getImplementationVersion();
        return new String[] {
            "carom " + (v != null ? v : "(development build)"),
            "Java " + System.getProperty("java.version") + " on " + System.getProperty("os.name")
        };
    }
}
