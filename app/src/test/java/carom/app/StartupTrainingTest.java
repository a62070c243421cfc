package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The start-up cache's training run ({@link StartupTraining}): it runs, tells failure, leaves nothing. */
class StartupTrainingTest {
    private static long trainingFolders() throws IOException {
        try (Stream<Path> tmp = Files.list(Path.of(System.getProperty("java.io.tmpdir")))) {
            return tmp.filter(p -> p.getFileName().toString().startsWith("carom-training")).count();
        }
    }

    @Test
    void trainsOnAnExampleAndRemovesItsScratchFolder() throws IOException {
        long before = trainingFolders();
        assertThat(StartupTraining.train(Path.of("..", "examples", "head-on.json"))).isTrue();
        assertThat(trainingFolders()).isEqualTo(before);
    }

    @Test
    void theClusterEnginesTrainingRunsOnTwoJvmsAndLeavesNoWorkerNorScratchFolder() throws IOException {
        long before = trainingFolders();
        assertThat(StartupTraining.trainCluster(Path.of("..", "examples", "head-on.json"))).isTrue();
        assertThat(trainingFolders()).isEqualTo(before);
        assertThat(ProcessHandle.current().descendants().filter(ProcessHandle::isAlive).toList()).as("workers left").isEmpty();
    }

    @Test
    void aSceneThatCannotBeReadIsAFailedTraining(@org.junit.jupiter.api.io.TempDir Path dir) throws IOException {
        long before = trainingFolders();
        assertThat(StartupTraining.train(dir.resolve("missing.json"))).isFalse();
        assertThat(StartupTraining.trainCluster(dir.resolve("missing.json"))).isFalse();
        assertThat(trainingFolders()).isEqualTo(before);
    }
}
