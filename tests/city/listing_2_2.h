// Listing 2.2 of Bilke 2009 (a rule file), shared by the parser's and the derivation's tests.
#pragma once

namespace veduta {

// Listing 2.2 of the thesis (L463–515) as printed, but for its last line, which the source
// truncates to "</Rulefile".
inline constexpr const char *kListing22 = R"(<?xml version="1.0" encoding="utf-8"?>
<Rulefile name="SimpleBuildingVar" xmlns:xsi="http://www.w3.org/2001/
  XMLSchema-instance" xsi:noNamespaceSchemaLocation="Rules.xsd">

  <!-- Eine Ersetzungsregel -->
  <Rule>
    <!-- Das Vorgängersymbol -->
    <Predecessor>FassadeStart</Predecessor>
    <Rules>
      <!-- Eine Substitution-Ableitungsregel -->
      <Probability value="0.5">
        <!-- Das Nachfolgersymbol -->
        <Symbol>Fassade1</Symbol>
      </Probability>
      <!-- Eine weitere Substitutions-Ableitungsregel -->
      <Probability value="0.5">
        <Symbol>Fassade2</Symbol>
      </Probability>
    </Rules>
  </Rule>

  <!-- Eine weitere Ersetzungsregel -->
  <Rule>
    <!-- Das Vorgängersymbol -->
    <Predecessor>Fassade1</Predecessor>
    <Rules>
      <!-- Eine Split-Ableitungsregel -->
      <Probability value="1.0">
        <Split axis="u"/>
        <Symbol size="4" texture="Bodenetage.jpg">
          Bodenetage.wrl
        </Symbol>
        <Symbol size="1r">WeitereEtagen</Symbol>
      </Probability>
    </Rules>
  </Rule>

  <!-- Eine weitere Ersetzungsregel -->
  <Rule>
    <!-- Das Vorgängersymbol -->
    <Predecessor>Fassade2</Predecessor>
    <Rules>
      <!-- Eine Repeat-Ableitungsregel -->
      <Probability value="1.0">
        <Repeat axis="r" size="1"/>
        <Symbol property="FassadenelementBreite">
          Fassadenelement
        </Symbol>
      </Probability>
    </Rules>
  </Rule>

</Rulefile>
)";

}  // namespace veduta
