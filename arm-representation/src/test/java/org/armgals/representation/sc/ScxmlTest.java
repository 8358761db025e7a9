package org.armgals.representation.sc;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Activation;
import org.armgals.representation.Step;
import org.junit.jupiter.api.Test;

class ScxmlTest {
  static String robot() {
    try (InputStream in = ScxmlTest.class.getResourceAsStream("robot.scxml")) {
      return new String(in.readAllBytes(), StandardCharsets.UTF_8);
    } catch (IOException e) {
      throw new AssertionError(e);
    }
  }

  static final Map<String, Guard> GUARDS =
      Map.of("notCharging", (c, in) -> !c.isActive("Charging"));

  @Test
  void readingGivesTheDocumentsStatesAndTransitions() {
    ScDefinition d = Scxml.read(robot());
    assertThat(d.name()).isEqualTo("explorer");
    assertThat(d.initial()).containsExactly("Active");
    assertThat(d.states()).extracting(ScNode::id).containsExactly("Active", "Charging", "Off");
    ScNode active = d.states().get(0);
    assertThat(active.initial()).containsExactly("Exploring");
    assertThat(active.children())
        .extracting(ScNode::kind)
        .containsExactly(ScNode.Kind.DEEP_HISTORY, ScNode.Kind.PARALLEL);
    assertThat(d.transitions())
        .extracting(ScTransition::id)
        .containsExactly(
            "Active#1", "Forward#1", "Turning#1", "Wide#1", "Zoom#1", "resume", "Charging#2");
    ScTransition bump = d.transitions().get(1);
    assertThat(bump.actions()).containsExactly(ScAction.run("beep"), ScAction.raise("obstacle"));
    assertThat(d.transitions().get(4).internal()).isTrue();
    assertThat(d.transitions().get(0).cond()).isEqualTo("notCharging");
  }

  @Test
  void readWriteReadGivesTheSameDefinition() {
    ScDefinition once = Scxml.read(robot());
    String written = Scxml.write(once);
    ScDefinition twice = Scxml.read(written);
    assertThat(twice).isEqualTo(once);
    assertThat(Scxml.write(twice)).isEqualTo(written);
  }

  @Test
  void aDefinitionBuiltInJavaSurvivesWriteAndRead() {
    ScDefinition robot = ScContractTest.ROBOT;
    ScDefinition back = Scxml.read(Scxml.write(robot));
    assertThat(back.states()).isEqualTo(robot.states());
    assertThat(new HashSet<>(back.transitions())).isEqualTo(new HashSet<>(robot.transitions()));
  }

  @Test
  void aChartReadFromScxmlRunsWithEntryExitActionsAndRaisedEvents() {
    Statechart chart = Statechart.of(Scxml.read(robot()), GUARDS);
    assertThat(chart.initialActions()).containsExactly("startMotors");
    Activation<Configuration> a = chart.activate(chart.initialState(), chart.transitions());
    List<Step<Configuration>> steps = a.dispatch("bump", null);
    assertThat(steps).extracting(Step::behavior).containsExactly("Forward#1", "Wide#1");
    assertThat(a.state().active()).contains("Turning", "Zoom");

    assertThat(a.dispatch("battery.low", null))
        .singleElement()
        .extracting(Step::result)
        .isEqualTo(List.of("stopMotors", "dock"));
    assertThat(a.dispatch("battery.full", null))
        .singleElement()
        .extracting(Step::result)
        .isEqualTo(List.of("startMotors"));
    assertThat(a.state().active()).contains("Turning", "Zoom");
  }

  @Test
  void anUnsupportedElementIsRefusedNamingItAndItsLine() {
    String doc =
        """
        <scxml xmlns="http://www.w3.org/2005/07/scxml" version="1.0">
          <state id="A">
            <invoke type="http://www.w3.org/TR/scxml/" src="other.scxml"/>
          </state>
        </scxml>
        """;
    assertThatThrownBy(() -> Scxml.read(doc))
        .isInstanceOf(ScxmlException.class)
        .hasMessageContaining("<invoke>")
        .hasMessageContaining("line 3")
        .satisfies(e -> assertThat(((ScxmlException) e).line()).isEqualTo(3));
  }

  @Test
  void aDataModelOtherThanNullOrEcmascriptOrAScriptIsRefused() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml" datamodel="xpath">
                      <state id="A"/>
                    </scxml>
                    """))
        .hasMessageContaining("xpath")
        .hasMessageContaining("line 1");
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A">
                        <onentry><script>x = 1</script></onentry>
                      </state>
                    </scxml>
                    """))
        .hasMessageContaining("<script>")
        .hasMessageContaining("line 3");
  }

  @Test
  void textInsideDataOrContentIsRefusedAsTheUnsupportedElementHoldingItWithItsLine() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A">
                        <datamodel>
                          <data id="x">42</data>
                        </datamodel>
                      </state>
                    </scxml>
                    """))
        .isInstanceOf(ScxmlException.class)
        .hasMessageContaining("element <datamodel> is not supported")
        .hasMessageNotContaining("text")
        .satisfies(e -> assertThat(((ScxmlException) e).line()).isEqualTo(3));
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A">
                        <invoke type="http://www.w3.org/TR/scxml/">
                          <content>hello</content>
                        </invoke>
                      </state>
                    </scxml>
                    """))
        .hasMessageContaining("element <invoke> is not supported")
        .hasMessageNotContaining("text")
        .satisfies(e -> assertThat(((ScxmlException) e).line()).isEqualTo(3));
  }

  // The same document gives the same message in every run: the supported attributes in the
  // order the reader lists them (a Set.of would list them in an order that changes between JVMs).
  @Test
  void anUnsupportedAttributeIsRefusedListingTheSupportedOnesInAFixedOrder() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml" binding="late">
                      <state id="A"/>
                    </scxml>
                    """))
        .hasMessageContaining(
            "attribute 'binding' of <scxml> is not supported; supported: [initial, name, version,"
                + " datamodel]");
  }

  @Test
  void textInASupportedElementIsRefusedNamingThatElementAndTheTextsLine() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A">
                        <onentry><raise event="e">now</raise></onentry>
                      </state>
                    </scxml>
                    """))
        .hasMessageContaining("text in <raise> is not supported")
        .satisfies(e -> assertThat(((ScxmlException) e).line()).isEqualTo(3));
  }

  @Test
  void anEcmascriptDocumentWhoseConditionsAreInTheLanguageIsAccepted() {
    ScDefinition d =
        Scxml.read(
            """
            <scxml xmlns="http://www.w3.org/2005/07/scxml" datamodel="ecmascript">
              <state id="A">
                <transition event="go" cond="_event.data.speed &gt; 10 &amp;&amp; In('A')"
                            target="B"/>
                <transition event="go" cond="ready" target="B"/>
              </state>
              <state id="B"/>
            </scxml>
            """);
    assertThat(d.transitions())
        .extracting(ScTransition::cond)
        .containsExactly("_event.data.speed > 10 && In('A')", "ready");
  }

  // A <log> is kept in the definition and written back, and has no effect when the chart runs
  // (decision 0049): a step's result lists only the actions the entity runs.
  @Test
  void aLogIsKeptAndWrittenBackAndHasNoEffect() {
    ScDefinition d =
        Scxml.read(
            """
            <scxml xmlns="http://www.w3.org/2005/07/scxml"
                   xmlns:arm="http://armgals.org/scxml" datamodel="ecmascript">
              <state id="A">
                <onexit><log label="leaving" expr="_event.name"/></onexit>
                <transition event="go" target="B">
                  <log expr="'going'"/><arm:action name="beep"/><log label="done"/>
                </transition>
              </state>
              <state id="B"/>
            </scxml>
            """);
    assertThat(d.states().get(0).onExit()).containsExactly(ScAction.log("leaving", "_event.name"));
    assertThat(d.transitions().get(0).actions())
        .containsExactly(
            ScAction.log(null, "'going'"), ScAction.run("beep"), ScAction.log("done", null));
    assertThat(Scxml.read(Scxml.write(d))).isEqualTo(d);
    Statechart chart = Statechart.of(d);
    Activation<Configuration> a = chart.activate(chart.initialState(), chart.transitions());
    assertThat(a.dispatch("go", null))
        .singleElement()
        .extracting(Step::result)
        .isEqualTo(List.of("beep"));
  }

  @Test
  void aLogWhoseExpressionIsBeyondTheLanguageIsRefusedWithItsLine() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml" datamodel="ecmascript">
                      <final id="A">
                        <onentry><log label="id" expr="'session ' + _sessionid"/></onentry>
                      </final>
                    </scxml>
                    """))
        .isInstanceOf(ScxmlException.class)
        .hasMessageContaining("<log>")
        .hasMessageContaining("_sessionid")
        .satisfies(e -> assertThat(((ScxmlException) e).line()).isEqualTo(3));
    assertThatThrownBy(() -> ScAction.log("x", "Var1"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'Var1'");
  }

  // Attribute values hold tabs and line breaks as references, which a parser keeps (a raw one
  // would come back as a space).
  @Test
  void tabsAndLineBreaksInAttributesSurviveTheRoundTrip() {
    ScDefinition d =
        ScDefinition.of("lines", ScNode.state("A").onEntry(ScAction.log("two\nlines\tand", "1")))
            .withTransitions(ScTransition.on("t", "A", "e", "A").when("true &&\n  true"));
    assertThat(Scxml.read(Scxml.write(d))).isEqualTo(d);
  }

  @Test
  void aConditionBeyondTheLanguageIsRefusedNamingTheConstructAndItsLine() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml" datamodel="ecmascript">
                      <state id="A">
                        <transition cond="Var1 == 0" target="B"/>
                      </state>
                      <state id="B"/>
                    </scxml>
                    """))
        .isInstanceOf(ScxmlException.class)
        .hasMessageContaining("'Var1'")
        .hasMessageContaining("condition language")
        .satisfies(e -> assertThat(((ScxmlException) e).line()).isEqualTo(3));
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml" datamodel="ecmascript">
                      <state id="A">
                        <transition cond="typeof _event.data === 'object'" target="A"/>
                      </state>
                    </scxml>
                    """))
        .hasMessageContaining("'typeof'")
        .hasMessageContaining("line 3");
  }

  @Test
  void anUnsupportedAttributeOrValueIsRefusedNamingIt() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A" src="x.scxml"/>
                    </scxml>
                    """))
        .hasMessageContaining("'src'")
        .hasMessageContaining("<state>")
        .hasMessageContaining("line 2");
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A">
                        <history id="H" type="sideways"/>
                        <state id="A1"/>
                      </state>
                    </scxml>
                    """))
        .hasMessageContaining("sideways")
        .hasMessageContaining("line 3");
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A"><transition event="e" type="sometimes" target="A"/></state>
                    </scxml>
                    """))
        .hasMessageContaining("sometimes");
  }

  @Test
  void aHistoryWithTwoDefaultTransitionsIsRefused() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A">
                        <history id="H">
                          <transition target="A1"/>
                          <transition target="A2"/>
                        </history>
                        <state id="A1"/>
                        <state id="A2"/>
                      </state>
                    </scxml>
                    """))
        .hasMessageContaining("second <transition>")
        .hasMessageContaining("line 5");
  }

  @Test
  void aStateWithoutIdIsRefused() {
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state/>
                    </scxml>
                    """))
        .hasMessageContaining("<state> has no id")
        .hasMessageContaining("line 2");
  }

  @Test
  void malformedXmlTextAndDoctypesAreRefusedWithTheLine() {
    assertThatThrownBy(
            () ->
                Scxml.read("<scxml xmlns=\"http://www.w3.org/2005/07/scxml\">\n<state id=\"A\">\n"))
        .isInstanceOf(ScxmlException.class)
        .hasMessageContaining("malformed");
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <scxml xmlns="http://www.w3.org/2005/07/scxml">
                      <state id="A">hello</state>
                    </scxml>
                    """))
        .hasMessageContaining("text")
        .hasMessageContaining("line 2");
    assertThatThrownBy(
            () ->
                Scxml.read(
                    """
                    <!DOCTYPE scxml [<!ENTITY x SYSTEM "file:///etc/passwd">]>
                    <scxml xmlns="http://www.w3.org/2005/07/scxml"><state id="A"/></scxml>
                    """))
        .isInstanceOf(ScxmlException.class)
        .hasMessageContaining("DOCTYPE");
    assertThatThrownBy(() -> Scxml.read("<scxml><state id=\"A\"/></scxml>"))
        .hasMessageContaining("not <scxml>");
  }

  // <send> to the chart itself, <if>, <donedata>: read into the records that say the same.
  @Test
  void sendIfAndDoneDataAreReadAsTheDefinitionSays() {
    ScDefinition d =
        Scxml.read(
            """
            <scxml xmlns="http://www.w3.org/2005/07/scxml" datamodel="ecmascript">
              <state id="A">
                <onentry>
                  <send event="tick"/>
                  <send eventexpr="_event.data.next" target="#_internal">
                    <param name="level" expr="3"/>
                    <param name="inA" expr="In('A')"/>
                  </send>
                  <send event="note" type="http://www.w3.org/TR/scxml/#SCXMLEventProcessor">
                    <content> some  text </content>
                  </send>
                  <if cond="_event.data.level &gt; 2">
                    <raise event="high"/>
                  <elseif cond="In('B')"/>
                  <else/>
                    <send event="low"><content expr="'v'"/></send>
                  </if>
                </onentry>
              </state>
              <final id="B">
                <donedata><param name="why" expr="'done'"/></donedata>
              </final>
            </scxml>
            """);
    ScNode a = d.states().get(0);
    assertThat(a.onEntry())
        .containsExactly(
            ScAction.send("tick"),
            ScAction.sendExpr("_event.data.next")
                .toInternalQueue()
                .with(ScData.params(ScData.param("level", "3"), ScData.param("inA", "In('A')"))),
            ScAction.send("note").with(ScData.text(" some  text ")),
            ScAction.when("_event.data.level > 2", ScAction.raise("high"))
                .orElseIf("In('B')")
                .orElse(ScAction.send("low").with(ScData.expr("'v'"))));
    assertThat(d.states().get(1).doneData())
        .isEqualTo(ScData.params(ScData.param("why", "'done'")));
    assertThat(Scxml.read(Scxml.write(d))).isEqualTo(d);
  }

  private static ScxmlException refusal(String content) {
    String document =
        """
        <scxml xmlns="http://www.w3.org/2005/07/scxml" datamodel="ecmascript">
          <state id="A">
            <onentry>
              %s
            </onentry>
          </state>
        </scxml>
        """
            .formatted(content);
    try {
      Scxml.read(document);
    } catch (ScxmlException e) {
      assertThat(e.line()).as(content).isEqualTo(4);
      return e;
    }
    throw new AssertionError("accepted: " + content);
  }

  // What the subset leaves out of <send> is refused, naming it: a delay, another target or I/O
  // processor, a target or type computed at run time, what needs a data model.
  @Test
  void aSendOutsideTheSubsetIsRefusedNamingWhatItNeeds() {
    assertThat(refusal("<send event=\"e\" delay=\"1s\"/>")).hasMessageContaining("with a delay");
    assertThat(refusal("<send event=\"e\" delayexpr=\"'1s'\"/>"))
        .hasMessageContaining("with a delay ('delayexpr')");
    assertThat(refusal("<send event=\"e\" target=\"#_parent\"/>"))
        .hasMessageContaining("target '#_parent' of <send> is not supported")
        .hasMessageContaining("the chart itself");
    assertThat(refusal("<send event=\"e\" target=\"#_scxml_other\"/>"))
        .hasMessageContaining("'#_scxml_other'");
    assertThat(refusal("<send event=\"e\" targetexpr=\"'#_internal'\"/>"))
        .hasMessageContaining("targetexpr");
    assertThat(
            refusal(
                "<send event=\"e\" type=\"http://www.w3.org/TR/scxml/#BasicHTTPEventProcessor\"/>"))
        .hasMessageContaining("BasicHTTPEventProcessor' of <send> is not supported");
    assertThat(refusal("<send event=\"e\" typeexpr=\"'scxml'\"/>"))
        .hasMessageContaining("typeexpr");
    assertThat(refusal("<send event=\"e\" namelist=\"x\"/>")).hasMessageContaining("data model");
    assertThat(refusal("<send event=\"e\" idlocation=\"x\"/>")).hasMessageContaining("data model");
    assertThat(refusal("<send event=\"e\" id=\"s1\"/>")).hasMessageContaining("<cancel>");
    assertThat(refusal("<send event=\"e\"><param name=\"p\" location=\"x\"/></send>"))
        .hasMessageContaining("location of <param>");
    assertThat(refusal("<send event=\"e\"><content><a xmlns=\"\"/></content></send>"))
        .hasMessageContaining("XML in <content>");
    assertThat(refusal("<send event=\"e\"><param name=\"p\" expr=\"x + 1\"/></send>"))
        .hasMessageContaining("expr of <param> is not in the condition language")
        .hasMessageContaining("'x' (a variable of a data model)");
    assertThat(refusal("<send eventexpr=\"'a' + 'b'\"/>"))
        .hasMessageContaining("ECMAScript's operator '+'");
  }

  // What the recommendation forbids in the elements the subset reads is refused too.
  @Test
  void aMalformedSendIfOrContentIsRefusedWithItsLine() {
    assertThat(refusal("<send/>")).hasMessageContaining("neither event nor eventexpr");
    assertThat(refusal("<send event=\"a\" eventexpr=\"'b'\"/>"))
        .hasMessageContaining("both event and eventexpr");
    assertThat(
            refusal("<send event=\"e\"><param name=\"p\" expr=\"1\"/><content>x</content></send>"))
        .hasMessageContaining("both <param> and <content>");
    assertThat(refusal("<send event=\"e\"><content expr=\"1\">x</content></send>"))
        .hasMessageContaining("both expr and text");
    assertThat(refusal("<if cond=\"true\"><else/><elseif cond=\"false\"/></if>"))
        .hasMessageContaining("<elseif> after <else>");
    assertThat(refusal("<if><raise event=\"e\"/></if>")).hasMessageContaining("no cond");
    // A named guard guards transitions; a branch's cond is in the condition language.
    assertThat(refusal("<if cond=\"ready\"><raise event=\"e\"/></if>"))
        .hasMessageContaining("cond of <if> is not in the condition language");
  }
}
