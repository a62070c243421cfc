package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Whatever a user gives (a value of megabytes, newlines, terminal escapes), an error is one {@code error:}
 * line of bounded length with the value escaped: in scene keys and string values, engine names, option
 * values and file names, in every command. A value quoted where it enters the message leaves it short;
 * messages that copy a value unquoted (picocli's, the engines') are still escaped and cut by
 * {@link ErrorReporting}.
 */
class ErrorLinesTest {
    @TempDir
    Path dir;

    /** What the user gave, in the three shapes that broke error messages. */
    private static String nasty(String kind) {
        return switch (kind) {
            // A million characters shows the bound as well as the 10 MB that once filled a terminal.
            case "long" -> "v".repeat(1_000_000);
            case "lines" -> "a\nerror: this line is fake\r\nb";
            default -> "\u001b[31mred\u001b[0m\u0007\u202eevil";
        };
    }

    /** A command line around the value, and whether carom quotes the value itself (so the line is short). */
    private record Case(String what, boolean quotedByCarom, Function<String, String[]> args) {
    }

    private List<Case> cases() {
        Path good = Scenes.write(dir, "good.json", Scenes.headOn());
        String scene = good.toString();
        String out = dir.resolve("out").toString();
        String headOn = Scenes.headOn();
        String firstDisc = "{ \"species\": \"disc\", \"x\": 2";
        String disc = "{ \"name\": \"disc\", \"radius\": 0.5, \"mass\": 1.0 }";
        List<Case> cases = new ArrayList<>();
        // In the scene file.
        cases.add(new Case("scene key", true,
                v -> simulate(headOn.replace("\"until\"", json(v) + ": 1, \"until\""))));
        cases.add(new Case("boundary", true, v -> simulate(headOn.replace("\"walls\"", json(v)))));
        cases.add(new Case("species reference", true,
                v -> simulate(headOn.replace(firstDisc, "{ \"species\": " + json(v) + ", \"x\": 2"))));
        cases.add(new Case("effect", true, v -> simulate(Scenes.headOn("{ " + json(v) + ": 1 }"))));
        cases.add(new Case("fixed species name (message of the scene builder)", false, v -> simulate(headOn
                .replace(disc, disc + ", { \"name\": " + json(v) + ", \"radius\": 0.1, \"fixed\": true }")
                .replace("\"particles\": [", "\"particles\": [ { \"species\": " + json(v)
                        + ", \"x\": 5, \"y\": 3.5, \"vx\": 1 },"))));
        // On the command line.
        cases.add(new Case("engine", true, v -> args("simulate", scene, "--engine", v)));
        cases.add(new Case("render engine", true, v -> args("render", scene, "--at", "1", "--out", out, "--engine", v)));
        cases.add(new Case("option key", true, v -> args("simulate", scene, "--option", v + "=1")));
        cases.add(new Case("option value (parsed by the engine)", false,
                v -> args("simulate", scene, "--option", "cellFactor=" + v)));
        cases.add(new Case("until (picocli)", false, v -> args("simulate", scene, "--until", v)));
        cases.add(new Case("threads (picocli)", false, v -> args("simulate", scene, "--threads", v)));
        cases.add(new Case("unknown option (picocli)", false, v -> args("simulate", scene, "--" + v)));
        cases.add(new Case("unknown command (picocli)", false, v -> args(v)));
        cases.add(new Case("render times", true, v -> args("render", scene, "--at", "1," + v, "--out", out)));
        cases.add(new Case("render colour", true, v -> args("render", scene, "--at", "1", "--out", out, "--color", v)));
        // File names.
        cases.add(new Case("scene file name", true, v -> args("simulate", dir.resolve(v).toString())));
        cases.add(new Case("render scene file name", true,
                v -> args("render", dir.resolve(v).toString(), "--at", "1", "--out", out)));
        cases.add(new Case("output directory", true,
                v -> args("simulate", scene, "--out", dir.resolve(v).resolve("f.csv").toString())));
        cases.add(new Case("render output directory", true,
                v -> args("render", scene, "--at", "1", "--out", dir.resolve(v).resolve("pictures").toString())));
        cases.add(new Case("recording file name", true, v -> args("analyze", dir.resolve(v).toString())));
        return cases;
    }

    private static String[] args(String... args) {
        return args;
    }

    private static String json(String value) {
        return JsonNodeFactory.instance.textNode(value).toString();
    }

    /** simulate on a scene file holding {@code json}. */
    private String[] simulate(String json) {
        return args("simulate", Scenes.write(dir, "nasty.json", json).toString());
    }

    @ParameterizedTest
    @ValueSource(strings = {"long", "lines", "escapes"})
    void everyErrorIsOneBoundedEscapedLine(String kind) {
        String value = nasty(kind);
        for (Case c : cases()) {
            Cli r = Cli.run(c.args().apply(value));
            String first = r.firstErrorLine();
            String what = c.what() + ": " + first.substring(0, Math.min(first.length(), 300));
            assertThat(r.status()).as(what).isEqualTo(2);
            assertThat(first).as(what).startsWith("error: ");
            // The message cut to its bound, then "... (N characters)".
            assertThat(first.length()).as(what).isLessThanOrEqualTo("error: ".length() + ErrorReporting.MAX_LINE_CHARS
                    + "... (2147483647 characters)".length());
            if (c.quotedByCarom()) {
                assertThat(first.length()).as(what).isLessThan(400);
            }
            assertThat(r.err()).as(what).doesNotContain("\u001b", "\u0007", "\r", "\u202e", "this line is fake\n");
            assertThat(r.err().lines().filter(l -> l.startsWith("error:"))).as(what).hasSize(1);
            if (!c.what().contains("picocli")) {
                assertThat(r.err().lines()).as("bad input is one line and nothing else: " + what).hasSize(1);
            }
            if (kind.equals("lines")) {
                assertThat(first).as(what).contains("\\n");
            }
        }
    }
}
