package carom.core;

import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;

/**
 * core's packages form layers, read bottom up: {@code state} (the discs), {@code grid} (cells over a
 * box), {@code scene} (the model, its builder and strict reader), {@code physics} (composed from a
 * scene), {@code observe} (measures of a state), {@code engine} (the engine interface and a run's
 * result). Each uses only packages below it, so each can be read and tested without those above it;
 * this test keeps the weakest form of that, no cycle between packages.
 */
@AnalyzeClasses(packages = "carom.core", importOptions = ImportOption.DoNotIncludeTests.class)
class PackageStructureTest {
    @ArchTest
    static final ArchRule noPackageCycles = slices().matching("carom.core.(*)..").should().beFreeOfCycles();
}
