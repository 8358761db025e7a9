package org.armgals.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.xpath.XPath;
import javax.xml.xpath.XPathConstants;
import javax.xml.xpath.XPathFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * What the build publishes, read from the POMs of this checkout: armgals-bom names every published
 * module at the build's version, and repeats armgals-parent's metadata (it has no parent, so
 * nothing keeps the two alike but this test); every published module names its JPMS module after a
 * package it has. A module is published unless its POM sets {@code maven.deploy.skip}.
 */
class ArtifactMetadataTest {
  private static final Path CHECKOUT = Path.of("").toAbsolutePath().getParent();
  private static final XPath XPATH = XPathFactory.newInstance().newXPath();

  @Test
  void theBomManagesEveryPublishedModuleAtTheBuildsVersion() throws Exception {
    Document root = pom(CHECKOUT.resolve("pom.xml"));
    Document bom = pom(CHECKOUT.resolve("armgals-bom/pom.xml"));

    assertThat(text(bom, "/project/groupId")).isEqualTo("org.armgals");
    assertThat(text(bom, "/project/version")).isEqualTo(text(root, "/project/version"));
    assertThat(text(bom, "/project/packaging")).isEqualTo("pom");
    assertThat(bom.getElementsByTagName("parent").getLength()).as("the BOM's parent").isZero();

    Map<String, String> managed = new TreeMap<>();
    NodeList dependencies =
        (NodeList)
            XPATH.evaluate(
                "/project/dependencyManagement/dependencies/dependency",
                bom,
                XPathConstants.NODESET);
    for (int i = 0; i < dependencies.getLength(); i++) {
      Node d = dependencies.item(i);
      assertThat(XPATH.evaluate("groupId", d)).isEqualTo("org.armgals");
      managed.put(XPATH.evaluate("artifactId", d), XPATH.evaluate("version", d));
    }
    assertThat(managed.keySet()).containsExactlyInAnyOrderElementsOf(publishedModules());
    assertThat(managed.values()).containsOnly("${project.version}");
  }

  @Test
  void theBomRepeatsTheParentsMetadata() throws Exception {
    Document root = pom(CHECKOUT.resolve("pom.xml"));
    Document bom = pom(CHECKOUT.resolve("armgals-bom/pom.xml"));
    for (String element :
        List.of(
            "url",
            "inceptionYear",
            "licenses",
            "developers",
            "scm/connection",
            "scm/developerConnection",
            "scm/url",
            "scm/tag")) {
      String expected = text(root, "/project/" + element);
      assertThat(expected).as("armgals-parent's <%s>", element).isNotBlank();
      assertThat(text(bom, "/project/" + element))
          .as("the BOM's <%s>", element)
          .isEqualTo(expected);
    }
    assertThat(text(bom, "/project/description")).isNotBlank();
    assertThat(text(bom, "/project/properties/project.build.outputTimestamp"))
        .isEqualTo(text(root, "/project/properties/project.build.outputTimestamp"));
  }

  @Test
  void everyPublishedModuleNamesItsJpmsModuleAfterOneOfItsPackages() throws Exception {
    for (String module : publishedModules()) {
      Document pom = pom(CHECKOUT.resolve(module).resolve("pom.xml"));
      String name = text(pom, "/project/properties/armgals.module.name");
      assertThat(name).as("%s's armgals.module.name", module).matches("org\\.armgals(\\.[a-z]+)+");
      Path sources = CHECKOUT.resolve(module).resolve("src/main/java");
      assertThat(sources.resolve(name.replace('.', '/')))
          .as("%s's module %s is one of its packages", module, name)
          .isDirectoryContaining(p -> p.toString().endsWith(".java"));
      assertThat(text(pom, "/project/description")).as("%s's description", module).isNotBlank();
    }
  }

  /** The modules of the root POM whose POM does not set {@code maven.deploy.skip}, but the BOM. */
  private static List<String> publishedModules() throws Exception {
    Document root = pom(CHECKOUT.resolve("pom.xml"));
    NodeList modules =
        (NodeList) XPATH.evaluate("/project/modules/module", root, XPathConstants.NODESET);
    List<String> published = new ArrayList<>();
    for (int i = 0; i < modules.getLength(); i++) {
      String module = modules.item(i).getTextContent().strip();
      Path pom = CHECKOUT.resolve(module).resolve("pom.xml");
      assertThat(pom).isRegularFile();
      if (module.equals("armgals-bom")
          || text(pom(pom), "/project/properties/maven.deploy.skip").equals("true")) {
        continue;
      }
      published.add(module);
    }
    assertThat(published).contains("arm-active", "maam-sim").doesNotContain("benchmarks");
    return published;
  }

  private static Document pom(Path file) throws Exception {
    assertThat(Files.isRegularFile(file)).as("%s exists", file).isTrue();
    return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());
  }

  /** The text of the element at {@code path}, its children's text run together and stripped. */
  private static String text(Document document, String path) throws Exception {
    Node node = (Node) XPATH.evaluate(path, document, XPathConstants.NODE);
    return node == null ? "" : node.getTextContent().replaceAll("\\s+", " ").strip();
  }
}
