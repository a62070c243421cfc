package carom.engines;

import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;

/**
 * The engines' packages use shared kernels (such as the step-grid kernel {@code cells}) and, for the
 * actor transports, the {@code actors} package, but never each other in a circle: each engine can be
 * read, tested and removed on its own.
 */
@AnalyzeClasses(packages = "carom.engines", importOptions = ImportOption.DoNotIncludeTests.class)
class PackageStructureTest {
    @ArchTest
    static final ArchRule noPackageCycles = slices().matching("carom.engines.(*)..").should().beFreeOfCycles();
}
