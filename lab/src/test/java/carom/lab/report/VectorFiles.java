package carom.lab.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.xml.parsers.DocumentBuilderFactory;
import org.w3c.dom.Document;

/** Checks that the vector plots are what they claim: SVG that an XML parser reads, with an svg root and text in it. */
public final class VectorFiles {
    private VectorFiles() {
    }

    /** Parses {@code svg} as XML (without fetching its DTD) and returns the document. */
    public static Document assertSvg(Path svg) throws IOException {
        return assertSvg(Files.readAllBytes(svg), svg.toString());
    }

    public static Document assertSvg(byte[] bytes, String what) {
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/nonvalidating/load-external-dtd", false);
            Document doc = factory.newDocumentBuilder().parse(new ByteArrayInputStream(bytes));
            assertThat(doc.getDocumentElement().getTagName()).as(what).isEqualTo("svg");
            assertThat(doc.getElementsByTagName("text").getLength() + doc.getElementsByTagName("path").getLength())
                    .as(what + ": drawn elements").isPositive();
            return doc;
        } catch (Exception e) {
            throw new AssertionError(what + " is not SVG that parses: " + e, e);
        }
    }
}
