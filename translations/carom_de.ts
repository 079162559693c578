<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>About</name>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="166" />
        <source>About Carom</source>
        <translation>Über Carom</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="169" />
        <source>Carom %1</source>
        <translation>Carom %1</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="172" />
        <source>A sandbox and scene editor for collision physics: balls, planes and cylinders under gravity, solved exactly or in steps.</source>
        <translation>Sandbox und Szeneneditor für Stoßphysik: Kugeln, Ebenen und Zylinder unter Schwerkraft, exakt oder in Schritten gelöst.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="177" />
        <source>Qt version %1</source>
        <translation>Qt-Version %1</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="178" />
        <source>Released under the MIT licence.</source>
        <translation>Veröffentlicht unter der MIT-Lizenz.</translation>
    </message>
</context>
<context>
    <name>Language</name>
    <message>
        <location filename="../ui/language.cpp" line="36" />
        <source>System Default</source>
        <translation>Systemstandard</translation>
    </message>
</context>
<context>
    <name>NumberText</name>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="43" />
        <source>“%1” is out of range</source>
        <translation>„%1“ liegt außerhalb des Wertebereichs</translation>
    </message>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="45" />
        <source>“%1” is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>ObjectRef</name>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="12" />
        <source>Plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="14" />
        <source>Cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="10" />
        <source>Ball</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="12" />
        <source>Planes</source>
        <translation>Ebenen</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="14" />
        <source>Cylinders</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="10" />
        <source>Balls</source>
        <translation>Kugeln</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="67" />
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="17" />
        <source>Box</source>
        <translation>Quader</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="17" />
        <source>Boxes</source>
        <translation>Quader</translation>
    </message>
</context>
<context>
    <name>ValidationText</name>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="104" />
        <source>Penetration tolerance</source>
        <translation>Eindringtoleranz</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="170" />
        <source>%1 would be %2 behind the surface of %3</source>
        <translation>%1 läge %2 hinter der Oberfläche von %3</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="173" />
        <source>%1 would overlap %2 by %3</source>
        <translation>%1 würde %2 um %3 überlappen</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="177" />
        <source>%1: at most %2 in a scene (this would make %3)</source>
        <translation>%1: höchstens %2 in einer Szene (es wären %3)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="184" />
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="189" />
        <source>%1 must be a finite number</source>
        <translation>%1 muss eine endliche Zahl sein</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="191" />
        <source>%1 must lie within ±%2 (got %3)</source>
        <translation>%1 muss innerhalb von ±%2 liegen (erhalten: %3)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="195" />
        <source>%1 must be above zero (got %2)</source>
        <translation>%1 muss größer als null sein (erhalten: %2)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="198" />
        <source>%1 must be at least %2 (got %3)</source>
        <translation>%1 muss mindestens %2 sein (erhalten: %3)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="201" />
        <source>%1 must be between %2 and %3 (got %4)</source>
        <translation>%1 muss zwischen %2 und %3 liegen (erhalten: %4)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="205" />
        <source>%1 must not be zero: it gives a direction</source>
        <translation>%1 darf nicht null sein: der Vektor gibt eine Richtung an</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/validation_text.cpp" line="209" />
        <source>%1 must be at most %n characters long (got %2)</source>
        <translation>
            <numerusform>%1 darf höchstens %n Zeichen lang sein (erhalten: %2)</numerusform>
            <numerusform>%1 darf höchstens %n Zeichen lang sein (erhalten: %2)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="214" />
        <source>%1 must be empty or a colour such as #ff8000 (got “%2”)</source>
        <translation>%1 muss leer oder eine Farbe wie #ff8000 sein (erhalten: „%2“)</translation>
    </message>
</context>
<context>
    <name>carom::editor::CylinderLengthField</name>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="35" />
        <source>Length (m):</source>
        <translation>Länge (m):</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="36" />
        <source>infinite</source>
        <translation>unendlich</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="37" />
        <source>The length of the cylinders Add Cylinder places; empty: infinite</source>
        <translation>Die Länge der Zylinder, die „Zylinder hinzufügen“ setzt; leer: unendlich</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="57" />
        <source>Cylinder length: %1</source>
        <translation>Zylinderlänge: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="59" />
        <source>Cylinder length: must be a positive number (got %1)</source>
        <translation>Zylinderlänge: muss eine positive Zahl sein (eingegeben: %1)</translation>
    </message>
</context>
<context>
    <name>carom::editor::EditorTools</name>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="82" />
        <source>Turn Plane</source>
        <translation>Ebene drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="92" />
        <source>Resize Cylinder</source>
        <translation>Zylinderlänge ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="96" />
        <source>Turn Cylinder</source>
        <translation>Zylinder drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="76" />
        <source>Change Velocity</source>
        <translation>Geschwindigkeit ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="364" />
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="445" />
        <source>Click on a surface or on the ground to place an object.</source>
        <translation>Klicken Sie auf eine Fläche oder den Boden, um ein Objekt zu platzieren.</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="467" />
        <source>Add Ball</source>
        <translation>Kugel hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="472" />
        <source>No room for a ball there: %1</source>
        <translation>Dort ist kein Platz für eine Kugel: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="483" />
        <source>Add Plane</source>
        <translation>Ebene hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="497" />
        <source>Add Cylinder</source>
        <translation>Zylinder hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="500" />
        <source>Cannot place it there: %1</source>
        <translation>Kann dort nicht platziert werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="486" />
        <source>Add Box</source>
        <translation>Quader hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="119" />
        <source>Resize Box</source>
        <translation>Quadergröße ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="110" />
        <source>Turn Box</source>
        <translation>Quader drehen</translation>
    </message>
</context>
<context>
    <name>carom::editor::OutlineDock</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="218" />
        <source>Outline</source>
        <translation>Übersicht</translation>
    </message>
</context>
<context>
    <name>carom::editor::OutlineModel</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="144" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="174" />
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
</context>
<context>
    <name>carom::editor::PropertiesDock</name>
    <message>
        <location filename="../ui/editor/number_field.cpp" line="52" />
        <location filename="../ui/editor/properties_dock.cpp" line="380" />
        <location filename="../ui/editor/properties_dock.cpp" line="503" />
        <location filename="../ui/editor/properties_dock.cpp" line="540" />
        <location filename="../ui/editor/properties_dock.cpp" line="563" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="68" />
        <location filename="../ui/editor/properties_dock.cpp" line="314" />
        <location filename="../ui/editor/validation_text.cpp" line="41" />
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="69" />
        <location filename="../ui/editor/validation_text.cpp" line="49" />
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70" />
        <location filename="../ui/editor/validation_text.cpp" line="57" />
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="71" />
        <location filename="../ui/editor/validation_text.cpp" line="99" />
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="72" />
        <location filename="../ui/editor/validation_text.cpp" line="96" />
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="73" />
        <location filename="../ui/editor/properties_dock.cpp" line="334" />
        <source>(any length)</source>
        <translation>(beliebige Länge)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="74" />
        <location filename="../ui/editor/validation_text.cpp" line="78" />
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="74" />
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80" />
        <location filename="../ui/editor/validation_text.cpp" line="93" />
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80" />
        <source>Change Colour</source>
        <translation>Farbe ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="87" />
        <location filename="../ui/editor/validation_text.cpp" line="46" />
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="87" />
        <location filename="../ui/editor/properties_dock.cpp" line="95" />
        <location filename="../ui/editor/properties_dock.cpp" line="113" />
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="89" />
        <location filename="../ui/editor/validation_text.cpp" line="48" />
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="89" />
        <source>Change Velocity</source>
        <translation>Geschwindigkeit ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="91" />
        <location filename="../ui/editor/properties_dock.cpp" line="109" />
        <location filename="../ui/editor/validation_text.cpp" line="54" />
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="91" />
        <location filename="../ui/editor/properties_dock.cpp" line="109" />
        <source>Change Radius</source>
        <translation>Radius ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="93" />
        <location filename="../ui/editor/validation_text.cpp" line="56" />
        <source>Mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="93" />
        <source>Change Mass</source>
        <translation>Masse ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="95" />
        <location filename="../ui/editor/validation_text.cpp" line="59" />
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101" />
        <location filename="../ui/editor/validation_text.cpp" line="61" />
        <source>Normal</source>
        <translation>Normale</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101" />
        <source>Turn Plane</source>
        <translation>Ebene drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="105" />
        <location filename="../ui/editor/validation_text.cpp" line="63" />
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="105" />
        <source>Turn Cylinder</source>
        <translation>Zylinder drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="120" />
        <location filename="../ui/editor/validation_text.cpp" line="95" />
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="120" />
        <source>Change Gravity</source>
        <translation>Schwerkraft ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="122" />
        <location filename="../ui/editor/validation_text.cpp" line="98" />
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="122" />
        <source>Change Time Step</source>
        <translation>Zeitschritt ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="124" />
        <location filename="../ui/editor/properties_dock.cpp" line="301" />
        <location filename="../ui/editor/validation_text.cpp" line="80" />
        <source>Restitution</source>
        <translation>Stoßzahl</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="124" />
        <location filename="../ui/editor/properties_dock.cpp" line="301" />
        <source>Change Restitution</source>
        <translation>Stoßzahl ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="126" />
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="126" />
        <source>Change Method</source>
        <translation>Methode ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="128" />
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="128" />
        <source>Change Integrator</source>
        <translation>Integrator ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="165" />
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="177" />
        <source>0 to 1; empty: the world's restitution</source>
        <translation>0 bis 1; leer: die Stoßzahl der Welt</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="178" />
        <source>Between the caps; empty: infinite</source>
        <translation>Zwischen den Deckeln; leer: unendlich</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="183" />
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="184" />
        <source>Choose a colour</source>
        <translation>Farbe wählen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="185" />
        <location filename="../ui/editor/properties_dock.cpp" line="580" />
        <source>Object Colour</source>
        <translation>Objektfarbe</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="313" />
        <location filename="../ui/editor/validation_text.cpp" line="65" />
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="313" />
        <source>Resize Cylinder</source>
        <translation>Zylinderlänge ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="326" />
        <location filename="../ui/editor/properties_dock.cpp" line="438" />
        <source>infinite</source>
        <translation>unendlich</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="374" />
        <source>World (nothing selected)</source>
        <translation>Welt (nichts ausgewählt)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="383" />
        <source>%1: %n selected</source>
        <translation>
            <numerusform>%1: %n ausgewählt</numerusform>
            <numerusform>%1: %n ausgewählt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="386" />
        <source>%n objects selected</source>
        <translation>
            <numerusform>%n Objekt ausgewählt</numerusform>
            <numerusform>%n Objekte ausgewählt</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="396" />
        <source>mixed</source>
        <translation>verschieden</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="416" />
        <source>default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="430" />
        <source>world's (%1)</source>
        <translation>der Welt (%1)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="113" />
        <location filename="../ui/editor/validation_text.cpp" line="67" />
        <source>Centre</source>
        <translation>Mittelpunkt</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="116" />
        <location filename="../ui/editor/validation_text.cpp" line="71" />
        <source>Half extents</source>
        <translation>Halbe Kantenlängen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="116" />
        <source>Resize Box</source>
        <translation>Quadergröße ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="333" />
        <location filename="../ui/editor/validation_text.cpp" line="73" />
        <source>Rotation axis</source>
        <translation>Drehachse</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="333" />
        <location filename="../ui/editor/properties_dock.cpp" line="343" />
        <source>Turn Box</source>
        <translation>Quader drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="343" />
        <location filename="../ui/editor/validation_text.cpp" line="75" />
        <source>Rotation</source>
        <translation>Drehung</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="344" />
        <location filename="../ui/editor/validation_text.cpp" line="76" />
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="453" />
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="182" />
        <source>Degrees about the axis, right-handed; empty: not turned</source>
        <translation>Grad um die Achse, rechtshändig; leer: nicht gedreht</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="51" />
        <source>Angular velocity</source>
        <translation>Winkelgeschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="52" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="82" />
        <source>Friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="84" />
        <source>Rolling resistance</source>
        <translation>Rollwiderstand</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="87" />
        <source>Spinning friction</source>
        <translation>Bohrreibung</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="90" />
        <source>Tangential restitution</source>
        <translation>Tangentiale Restitution</translation>
    </message>
</context>
<context>
    <name>carom::editor::SceneDocument</name>
    <message>
        <location filename="../ui/editor/scene_document.cpp" line="97" />
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../ui/editor/scene_document.cpp" line="111" />
        <source>floor</source>
        <translation>Boden</translation>
    </message>
</context>
<context>
    <name>carom::ui</name>
    <message>
        <location filename="../ui/watch_text.cpp" line="24" />
        <source>ball %1 (%2)</source>
        <translation>Kugel %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="25" />
        <source>ball %1</source>
        <translation>Kugel %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="39" />
        <source>plane %1</source>
        <translation>Ebene %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="41" />
        <source>cylinder %1</source>
        <translation>Zylinder %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="44" />
        <source>box %1</source>
        <translation>Quader %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="58" />
        <source>At %1 s %2 has a position or velocity that is not a finite number.</source>
        <translation>Bei %1 s hat %2 eine Position oder Geschwindigkeit, die keine endliche Zahl ist.</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="61" />
        <source>At %1 s the energy rose by %2 of the scene's energy scale (tolerance %3); %4 gained the most.</source>
        <translation>Bei %1 s stieg die Energie um %2 der Energieskala der Szene (Toleranz %3); %4 gewann am meisten.</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="65" />
        <source>At %1 s %2 got inside %3: its centre is %4 of its radius past the surface.</source>
        <translation>Bei %1 s geriet %2 in %3: Ihr Mittelpunkt liegt %4 ihres Radius hinter der Oberfläche.</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="68" />
        <source>At %1 s %2 overlaps %3 by %4 of the radius (tolerance %5).</source>
        <translation>Bei %1 s überlappt %2 mit %3 um %4 des Radius (Toleranz %5).</translation>
    </message>
</context>
<context>
    <name>carom::ui::AccuracyWindow</name>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="161" />
        <source>Speed vs accuracy</source>
        <translation>Geschwindigkeit und Genauigkeit</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="163" />
        <source>Position error against exact at the horizon (m)</source>
        <translation>Positionsfehler gegenüber exact am Horizont (m)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="164" />
        <source>Relative energy drift</source>
        <translation>Relative Energiedrift</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="165" />
        <source>Deepest penetration (m)</source>
        <translation>Maximale Eindringtiefe (m)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="166" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="403" />
        <source>Escaped balls</source>
        <translation>Entwichene Kugeln</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="167" />
        <source>Speed distribution against exact (KS distance)</source>
        <translation>Geschwindigkeitsverteilung gegenüber exact (KS-Abstand)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="168" />
        <source>Position distribution against exact (KS distance)</source>
        <translation>Positionsverteilung gegenüber exact (KS-Abstand)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="169" />
        <source>Energy error per simulated second (auto's measure)</source>
        <translation>Energiefehler je simulierter Sekunde (Maß von auto)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="172" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <source>Computing time (s)</source>
        <translation>Rechenzeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="173" />
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="174" />
        <source>Cheapest within the tolerance</source>
        <translation>Günstigster innerhalb der Toleranz</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="175" />
        <source>Chosen run</source>
        <translation>Gewählter Lauf</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <source>Position error at horizon (m)</source>
        <translation>Positionsfehler am Horizont (m)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="182" />
        <source>Each point is one run of the current scene; lower and further left is better. Choose a run to use its settings. Paths part from exact ones with time, whatever the method: position error is taken at the horizon up to which the finest setting agrees with exact, and whole runs are judged by energy, penetration, escapes and distributions.</source>
        <translation>Jeder Punkt ist ein Lauf der aktuellen Szene; weiter unten und weiter links ist besser. Wählen Sie einen Lauf, um seine Einstellungen zu übernehmen. Bahnen entfernen sich mit der Zeit von den exakten, bei jeder Methode: Der Positionsfehler wird am Horizont gemessen, bis zu dem die feinste Einstellung mit exact übereinstimmt, und ganze Läufe werden nach Energie, Eindringen, Ausbrüchen und Verteilungen beurteilt.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="317" />
        <source>position error at the horizon</source>
        <translation>Positionsfehler am Horizont</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="318" />
        <source>at most %1 m, a tenth of the mean radius: as close as the finest setting stays to exact up to the horizon</source>
        <translation>höchstens %1 m, ein Zehntel des mittleren Radius: so nah, wie die feinste Einstellung bis zum Horizont an exact bleibt</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="323" />
        <source>relative energy drift</source>
        <translation>relativen Energiedrift</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="324" />
        <source>at most %1: auto's energy error per second times the %2 s of the run</source>
        <translation>höchstens %1: der Energiefehler pro Sekunde von auto mal die %2 s des Laufs</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="328" />
        <source>deepest penetration</source>
        <translation>tiefsten Eindringen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="329" />
        <source>at most %1 m: auto's %2 % of the smallest radius</source>
        <translation>höchstens %1 m: die %2 % des kleinsten Radius von auto</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="333" />
        <source>escaped balls</source>
        <translation>entkommenen Kugeln</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="334" />
        <source>none, as auto asks</source>
        <translation>keine, wie auto verlangt</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="339" />
        <source>speed distribution against exact</source>
        <translation>Geschwindigkeitsverteilung gegenüber exact</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="340" />
        <source>position distribution against exact</source>
        <translation>Positionsverteilung gegenüber exact</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/accuracy_window.cpp" line="341" />
        <source>a KS distance of at most %1: %Ln balls cannot tell it from exact's at 5 % significance</source>
        <translation>
            <numerusform>ein KS-Abstand von höchstens %1: %Ln Kugel kann sie bei 5 % Signifikanz nicht von der exakten unterscheiden</numerusform>
            <numerusform>ein KS-Abstand von höchstens %1: %Ln Kugeln können sie bei 5 % Signifikanz nicht von der exakten unterscheiden</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="347" />
        <source>energy error per simulated second</source>
        <translation>Energiefehler pro simulierter Sekunde</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="348" />
        <source>at most %1 per second, auto's accuracy</source>
        <translation>höchstens %1 pro Sekunde, die Genauigkeit von auto</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="352" />
        <source>Tolerance on %1: %2. Ringed: the cheapest run within it.</source>
        <translation>Toleranz für %1: %2. Umkreist: der günstigste Lauf darin.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="402" />
        <source>Position error (m)</source>
        <translation>Positionsfehler (m)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="404" />
        <source>Speeds (KS distance)</source>
        <translation>Geschwindigkeiten (KS-Abstand)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="404" />
        <source>Positions (KS distance)</source>
        <translation>Positionen (KS-Abstand)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="405" />
        <source>Energy error per second</source>
        <translation>Energiefehler pro Sekunde</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="428" />
        <source>Each run: %1 s simulated</source>
        <translation>Jeder Lauf: %1 s simuliert</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="432" />
        <source>%1; the finest setting agrees with exact up to %2 s</source>
        <translation>%1; die feinste Einstellung stimmt bis %2 s mit exact überein</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="435" />
        <source>%1; even the finest setting parts from exact at once: no position error</source>
        <translation>%1; selbst die feinste Einstellung weicht sofort von exact ab: kein Positionsfehler</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="402" />
        <source>Energy drift</source>
        <translation>Energiedrift</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <source>Escaped</source>
        <translation>Entwichen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="403" />
        <source>Penetration (m)</source>
        <translation>Eindringtiefe (m)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <source>Speeds (KS)</source>
        <translation>Geschwindigkeiten (KS)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <source>Positions (KS)</source>
        <translation>Positionen (KS)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="179" />
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="180" />
        <source>Apply Selected Settings</source>
        <translation>Ausgewählte Einstellungen übernehmen</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/accuracy_window.cpp" line="272" />
        <source>%Ln runs</source>
        <translation>
            <numerusform>%Ln Lauf</numerusform>
            <numerusform>%Ln Läufe</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="278" />
        <source>Cancelled after %1 in %2 s.</source>
        <translation>Abgebrochen nach %1 in %2 s.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/accuracy_window.cpp" line="281" />
        <source>%Ln threads</source>
        <translation>
            <numerusform>%Ln Thread</numerusform>
            <numerusform>%Ln Threads</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="287" />
        <source>%1 in %2 s on %3, no faster than one after another</source>
        <translation>%1 in %2 s mit %3, nicht schneller als nacheinander</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="290" />
        <source>%1 in %2 s on %3, %4× faster than one after another</source>
        <translation>%1 in %2 s mit %3, %4× schneller als nacheinander</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="162" />
        <source>Error:</source>
        <translation>Fehler:</translation>
    </message>
</context>
<context>
    <name>carom::ui::AutoMethod</name>
    <message>
        <location filename="../ui/auto_method.cpp" line="24" />
        <source>%1 (%2, step %3 s)</source>
        <translation>%1 (%2, Schritt %3 s)</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="102" />
        <source>Auto: no setting meets the accuracy; the settings are kept</source>
        <translation>Auto: keine Einstellung erreicht die Genauigkeit; die Einstellungen bleiben</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="103" />
        <source>No setting meets an energy error of %1 per second; the closest is %2. The settings are kept.</source>
        <translation>Keine Einstellung erreicht einen Energiefehler von %1 je Sekunde; am nächsten kommt %2. Die Einstellungen bleiben.</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="113" />
        <source>Auto: %1</source>
        <translation>Auto: %1</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="118" />
        <source>Auto chose %1</source>
        <translation>Auto wählte %1</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="119" />
        <source>Auto chose %1: the cheapest setting with an energy error under %2 per second (%3 s of computing per simulated second; pilot %4 s).</source>
        <translation>Auto wählte %1: die günstigste Einstellung mit einem Energiefehler unter %2 je Sekunde (%3 s Rechenzeit je simulierter Sekunde; Vorlauf %4 s).</translation>
    </message>
    <message>
        <source>Auto: no setting meets an energy error of %1 per second; the closest is %2. The settings are kept.</source>
        <translation type="vanished">Auto: Keine Einstellung erreicht einen Energiefehler von %1 je Sekunde; am nächsten kommt %2. Die Einstellungen bleiben.</translation>
    </message>
    <message>
        <source>Choose Method Automatically</source>
        <translation type="vanished">Methode automatisch wählen</translation>
    </message>
    <message>
        <source>Auto chose %1: the cheapest setting with an energy error under %2 per second (%3 s of computing per simulated second; pilot %4 s)</source>
        <translation type="vanished">Auto wählte %1: die günstigste Einstellung mit einem Energiefehler unter %2 je Sekunde (%3 s Rechenzeit je simulierter Sekunde; Vorlauf %4 s)</translation>
    </message>
</context>
<context>
    <name>carom::ui::BallStoryDock</name>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="105" />
        <source>Ball Story</source>
        <translation>Kugelverlauf</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="107" />
        <source>Height (m)</source>
        <translation>Höhe (m)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="108" />
        <source>Speed (m/s)</source>
        <translation>Geschwindigkeit (m/s)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="109" />
        <source>Energy (J)</source>
        <translation>Energie (J)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="111" />
        <source>Height is measured against gravity (along y when there is none); energy is the ball's kinetic energy plus its potential energy relative to the origin.</source>
        <translation>Die Höhe wird entgegen der Schwerkraft gemessen (ohne Schwerkraft entlang y); die Energie ist die kinetische Energie der Kugel plus ihre potentielle Energie relativ zum Ursprung.</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="115" />
        <source>Simulated time (s)</source>
        <translation>Simulierte Zeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="122" />
        <source>Select balls to follow them: their story starts when they are selected.</source>
        <translation>Wählen Sie Kugeln aus, um ihnen zu folgen: Ihr Verlauf beginnt mit der Auswahl.</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="124" />
        <source>Showing the first %1 of %2 selected balls; each story starts when the ball is selected.</source>
        <translation>Gezeigt werden die ersten %1 von %2 ausgewählten Kugeln; jeder Verlauf beginnt mit der Auswahl der Kugel.</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="129" />
        <source>Each ball's story starts when it is selected.</source>
        <translation>Der Verlauf jeder Kugel beginnt mit ihrer Auswahl.</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditActions</name>
    <message>
        <location filename="../ui/edit_actions.cpp" line="34" />
        <source>clipboard</source>
        <translation>Zwischenablage</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="36" />
        <source>Nothing to paste: %1</source>
        <translation>Nichts einzufügen: %1</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="39" />
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="43" />
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="47" />
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="81" />
        <source>Cannot place the objects: %1</source>
        <translation>Die Objekte können nicht platziert werden: %1</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditMenu</name>
    <message>
        <location filename="../ui/edit_menu.cpp" line="68" />
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="57" />
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="59" />
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederholen: %1</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="56" />
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="58" />
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="70" />
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="71" />
        <source>&amp;Paste</source>
        <translation>E&amp;infügen</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="72" />
        <source>&amp;Duplicate</source>
        <translation>&amp;Duplizieren</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="73" />
        <source>De&amp;lete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="74" />
        <source>Select &amp;All</source>
        <translation>&amp;Alles auswählen</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditorToolBar</name>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Select</source>
        <translation>Auswählen</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Add Ball</source>
        <translation>Kugel hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Add Plane</source>
        <translation>Ebene hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Add Cylinder</source>
        <translation>Zylinder hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="75" />
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="80" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="83" />
        <source>Snap to &amp;Grid</source>
        <translation>Am &amp;Raster ausrichten</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="85" />
        <source>Moves land on multiples of %1 m</source>
        <translation>Verschiebungen landen auf Vielfachen von %1 m</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="74" />
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="77" />
        <source>Add Box</source>
        <translation>Quader hinzufügen</translation>
    </message>
</context>
<context>
    <name>carom::ui::EnergyPlot</name>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="67" />
        <source>Kinetic</source>
        <translation>Kinetisch</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="68" />
        <source>Potential</source>
        <translation>Potentiell</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="69" />
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="70" />
        <source>Simulated time (s)</source>
        <translation>Simulierte Zeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="71" />
        <source>Energy (J)</source>
        <translation>Energie (J)</translation>
    </message>
</context>
<context>
    <name>carom::ui::ExamplesMenu</name>
    <message>
        <location filename="../ui/examples_menu.cpp" line="26" />
        <source>&amp;Examples</source>
        <translation>&amp;Beispiele</translation>
    </message>
</context>
<context>
    <name>carom::ui::FileMenu</name>
    <message>
        <location filename="../ui/file_menu.cpp" line="64" />
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="67" />
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="65" />
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="66" />
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="68" />
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="69" />
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="70" />
        <source>Export &amp;Image…</source>
        <translation>Bild &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="71" />
        <source>Export &amp;Video…</source>
        <translation>&amp;Video exportieren…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="55" />
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="72" />
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
</context>
<context>
    <name>carom::ui::GrabControl</name>
    <message>
        <location filename="../ui/grab_control.cpp" line="65" />
        <source>Throw Speed Limit</source>
        <translation>Wurfgeschwindigkeitsgrenze</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="66" />
        <source>Fastest throw of a grabbed ball (m/s):</source>
        <translation>Schnellster Wurf einer gegriffenen Kugel (m/s):</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="80" />
        <source>The grab stopped at t = %1 s: ball %2 would have been crushed against what is behind it.</source>
        <translation>Das Greifen endete bei t = %1 s: Kugel %2 wäre gegen das dahinter zerquetscht worden.</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="85" />
        <source>The grab stopped at t = %1 s: the balls in front are jammed.</source>
        <translation>Das Greifen endete bei t = %1 s: die Kugeln davor sind verklemmt.</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="88" />
        <source>Thrown at the throw limit, %1 m/s (Simulation &gt; Throw Speed Limit).</source>
        <translation>Mit der Wurfgrenze von %1 m/s geworfen (Simulation &gt; Wurfgeschwindigkeitsgrenze).</translation>
    </message>
</context>
<context>
    <name>carom::ui::HelpMenu</name>
    <message>
        <location filename="../ui/help_menu.cpp" line="40" />
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <location filename="../ui/help_menu.cpp" line="38" />
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../ui/help_menu.cpp" line="39" />
        <source>&amp;Keyboard and Mouse</source>
        <translation>&amp;Tastatur und Maus</translation>
    </message>
    <message>
        <location filename="../ui/help_menu.cpp" line="41" />
        <source>&amp;About Carom</source>
        <translation>Ü&amp;ber Carom</translation>
    </message>
</context>
<context>
    <name>carom::ui::HelpWindow</name>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="72" />
        <source>Keyboard and Mouse</source>
        <translation>Tastatur und Maus</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="77" />
        <source>User Guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="78" />
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="87" />
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="88" />
        <source>Run or pause the simulation</source>
        <translation>Simulation starten oder anhalten</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="89" />
        <source>Advance one time step, paused</source>
        <translation>Einen Zeitschritt weiter, dann angehalten</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="90" />
        <source>Back to the scene's initial state, paused</source>
        <translation>Zurück zum Anfangszustand der Szene, angehalten</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="91" />
        <source>Larger time step (×1.25)</source>
        <translation>Größerer Zeitschritt (×1,25)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="92" />
        <source>Smaller time step (÷1.25)</source>
        <translation>Kleinerer Zeitschritt (÷1,25)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="93" />
        <source>Up, Down, wheel over a toolbar box</source>
        <translation>Pfeil hoch, Pfeil runter, Mausrad über einem Feld der Werkzeugleiste</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="93" />
        <source>Change its value by a step</source>
        <translation>Seinen Wert um einen Schritt ändern</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="94" />
        <source>Typing in a toolbar box, then Enter</source>
        <translation>In ein Feld der Werkzeugleiste tippen, dann Eingabe</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="94" />
        <source>Set the value exactly</source>
        <translation>Den Wert genau setzen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="95" />
        <source>Mute or unmute the collision sounds</source>
        <translation>Stoßgeräusche stumm- oder wieder einschalten</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="96" />
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="97" />
        <source>Left drag on empty space</source>
        <translation>Ziehen mit der linken Taste auf freier Fläche</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="97" />
        <source>Orbit the camera round the scene</source>
        <translation>Die Kamera um die Szene kreisen lassen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="98" />
        <source>Middle drag</source>
        <translation>Ziehen mit der mittleren Taste</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="98" />
        <source>Pan the camera</source>
        <translation>Die Kamera verschieben</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="99" />
        <source>Mouse wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="99" />
        <source>Zoom</source>
        <translation>Zoomen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="100" />
        <source>Arrow keys (in the view)</source>
        <translation>Pfeiltasten (in der Ansicht)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="100" />
        <source>Rotate the camera</source>
        <translation>Die Kamera drehen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="101" />
        <source>Frame the whole scene</source>
        <translation>Die ganze Szene ins Bild holen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="102" />
        <source>Follow the selected ball, or the first one; again to stop</source>
        <translation>Der ausgewählten Kugel folgen, sonst der ersten; noch einmal zum Beenden</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="103" />
        <source>Full screen on or off</source>
        <translation>Vollbild ein oder aus</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="104" />
        <source>Editing tools</source>
        <translation>Bearbeitungswerkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="105" />
        <source>Select: click to pick, drag to move</source>
        <translation>Auswählen: klicken zum Wählen, ziehen zum Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="106" />
        <source>Add Ball</source>
        <translation>Kugel hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="107" />
        <source>Add Plane</source>
        <translation>Ebene hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="108" />
        <source>Add Cylinder</source>
        <translation>Zylinder hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="110" />
        <source>Click with an Add tool</source>
        <translation>Klick mit einem Hinzufügen-Werkzeug</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="111" />
        <source>Place the object where the cursor points, on a surface or the ground</source>
        <translation>Das Objekt dort platzieren, wohin der Zeiger weist, auf einer Fläche oder dem Boden</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="112" />
        <source>Selecting and moving</source>
        <translation>Auswählen und Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="113" />
        <source>Click</source>
        <translation>Klick</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="113" />
        <source>Select the object under the cursor; on nothing, clear the selection</source>
        <translation>Das Objekt unter dem Zeiger auswählen; ins Leere: die Auswahl aufheben</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="114" />
        <source>Ctrl+click, Shift+click</source>
        <translation>Strg+Klick, Umschalt+Klick</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="114" />
        <source>Add the object to the selection or take it out</source>
        <translation>Das Objekt zur Auswahl hinzufügen oder herausnehmen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="115" />
        <source>Drag a selected object</source>
        <translation>Ein ausgewähltes Objekt ziehen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="115" />
        <source>Move the selection in the plane facing the camera</source>
        <translation>Die Auswahl in der Ebene verschieben, die der Kamera zugewandt ist</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="116" />
        <source>X, Y or Z held while dragging</source>
        <translation>X, Y oder Z beim Ziehen gedrückt</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="116" />
        <source>Move along that axis only</source>
        <translation>Nur entlang dieser Achse verschieben</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="117" />
        <source>Drag the tip of the arrow</source>
        <translation>Die Pfeilspitze ziehen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="118" />
        <source>Change a ball's velocity, a plane's normal or a cylinder's axis</source>
        <translation>Die Geschwindigkeit einer Kugel, die Normale einer Ebene oder die Achse eines Zylinders ändern</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="119" />
        <source>Alt+drag from a ball</source>
        <translation>Alt+Ziehen von einer Kugel aus</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="119" />
        <source>Draw the ball's velocity, also for a ball at rest</source>
        <translation>Die Geschwindigkeit der Kugel zeichnen, auch für eine ruhende Kugel</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="120" />
        <source>Escape while dragging or grabbing</source>
        <translation>Esc beim Ziehen oder Greifen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="121" />
        <source>Cancel the drag: everything as it was before the press</source>
        <translation>Ziehen abbrechen: alles wie vor dem Drücken</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="122" />
        <source>Running world</source>
        <translation>Laufende Welt</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="123" />
        <source>Drag a ball once the run has begun</source>
        <translation>Eine Kugel ziehen, sobald der Lauf begonnen hat</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="124" />
        <source>Grab it: it follows the cursor and pushes other balls; let go to throw it</source>
        <translation>Sie greifen: sie folgt dem Zeiger und schiebt andere Kugeln; loslassen wirft sie</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="125" />
        <source>X, Y or Z held while grabbing</source>
        <translation>X, Y oder Z beim Greifen gedrückt</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="125" />
        <source>Keep the grabbed ball on that axis</source>
        <translation>Die gegriffene Kugel auf dieser Achse halten</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="126" />
        <source>Drag the timeline under the view</source>
        <translation>Die Zeitleiste unter der Ansicht ziehen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="127" />
        <source>Show an earlier moment; Run goes on from there and forgets the rest</source>
        <translation>Einen früheren Moment zeigen; Starten setzt dort fort und vergisst den Rest</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="128" />
        <source>Arrows, Page Up/Down, Home, End (on the timeline)</source>
        <translation>Pfeile, Bild auf/ab, Pos1, Ende (auf der Zeitleiste)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="129" />
        <source>Step through the recorded frames</source>
        <translation>Durch die aufgezeichneten Bilder gehen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="130" />
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="131" />
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="132" />
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="133" />
        <source>Copy the selection (as scene text)</source>
        <translation>Die Auswahl kopieren (als Szenentext)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="134" />
        <source>Paste objects, moved aside where they would overlap</source>
        <translation>Objekte einfügen, zur Seite gerückt, wo sie sich überschneiden würden</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="135" />
        <source>Duplicate the selection</source>
        <translation>Die Auswahl duplizieren</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="136" />
        <source>Delete the selection</source>
        <translation>Die Auswahl löschen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="137" />
        <source>Select every object</source>
        <translation>Alle Objekte auswählen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="138" />
        <source>Files</source>
        <translation>Dateien</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="139" />
        <source>New scene</source>
        <translation>Neue Szene</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="140" />
        <source>Open a scene</source>
        <translation>Eine Szene öffnen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="141" />
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="142" />
        <source>Save under another name</source>
        <translation>Unter anderem Namen speichern</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="143" />
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="144" />
        <source>Dropping a file on the window</source>
        <translation>Eine Datei auf das Fenster ziehen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="144" />
        <source>Open it</source>
        <translation>Sie öffnen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="145" />
        <source>Outline and Properties</source>
        <translation>Übersicht und Eigenschaften</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="146" />
        <source>Click, Ctrl+click, Shift+click</source>
        <translation>Klick, Strg+Klick, Umschalt+Klick</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="146" />
        <source>Select objects, as in the view</source>
        <translation>Objekte auswählen, wie in der Ansicht</translation>
    </message>
    <message>
        <source>Double-click, F2 (in the outline)</source>
        <translation type="vanished">Doppelklick, F2 (in der Übersicht)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="147" />
        <source>Rename the object</source>
        <translation>Das Objekt umbenennen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="147" />
        <source>Double-click (in the outline)</source>
        <translation>Doppelklick (in der Übersicht)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="148" />
        <source>Enter, or leaving a field</source>
        <translation>Eingabe oder Verlassen eines Feldes</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="148" />
        <source>Apply the typed value</source>
        <translation>Den eingegebenen Wert übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="149" />
        <source>Speed vs Accuracy</source>
        <translation>Geschwindigkeit und Genauigkeit</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="150" />
        <source>Click a point</source>
        <translation>Klick auf einen Punkt</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="150" />
        <source>Select its run in the table</source>
        <translation>Seinen Lauf in der Tabelle auswählen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="151" />
        <source>Double-click a run</source>
        <translation>Doppelklick auf einen Lauf</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="151" />
        <source>Apply its settings to the scene</source>
        <translation>Seine Einstellungen auf die Szene anwenden</translation>
    </message>
    <message>
        <source>Physics Notes</source>
        <translation type="vanished">Physik-Notizen</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="109" />
        <source>Add Box</source>
        <translation>Quader hinzufügen</translation>
    </message>
</context>
<context>
    <name>carom::ui::HistoryDock</name>
    <message>
        <location filename="../ui/docks/history_dock.cpp" line="19" />
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
</context>
<context>
    <name>carom::ui::ImageExport</name>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="114" />
        <source>Export Image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="115" />
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="121" />
        <source>Cannot Export Image</source>
        <translation>Bild kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="124" />
        <source>Exported a %1×%2 image to %3</source>
        <translation>Bild mit %1×%2 Pixeln nach %3 exportiert</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="140" />
        <source>The graphics driver could not draw a %1×%2 picture.</source>
        <translation>Der Grafiktreiber konnte kein Bild mit %1×%2 Pixeln zeichnen.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="154" />
        <source>Could not write %1: %2</source>
        <translation>%1 konnte nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::ImageSizeDialog</name>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="41" />
        <source>Export Image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="51" />
        <source>Width (pixels)</source>
        <translation>Breite (Pixel)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="52" />
        <source>Height (pixels)</source>
        <translation>Höhe (Pixel)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="65" />
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="65" />
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="69" />
        <source>%1: must be a whole number of pixels (got "%2")</source>
        <translation>%1: muss eine ganze Zahl von Pixeln sein (erhalten: „%2“)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="71" />
        <source>%1: must be between %2 and %3 pixels (got %4)</source>
        <translation>%1: muss zwischen %2 und %3 Pixeln liegen (erhalten: %4)</translation>
    </message>
</context>
<context>
    <name>carom::ui::LanguageMenu</name>
    <message>
        <location filename="../ui/language_menu.cpp" line="39" />
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
</context>
<context>
    <name>carom::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="233" />
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="232" />
        <source>&amp;Follow Ball</source>
        <translation>Kugel &amp;folgen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="260" />
        <source>%1[*] — Carom</source>
        <translation>%1[*] — Carom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="287" />
        <source>Apply Settings</source>
        <translation>Einstellungen übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="128" />
        <source>The recovery copy could not be written (%1); the last one is kept. Save the scene elsewhere to be safe.</source>
        <translation>Die Wiederherstellungskopie konnte nicht geschrieben werden (%1); die letzte bleibt erhalten. Speichern Sie die Szene sicherheitshalber an einem anderen Ort.</translation>
    </message>
    <message>
        <source>&amp;Physics Notes</source>
        <translation type="vanished">&amp;Physik-Notizen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="368" />
        <source>Use Current State as Initial</source>
        <translation>Aktuellen Zustand als Anfang übernehmen</translation>
    </message>
</context>
<context>
    <name>carom::ui::NumberBox</name>
    <message>
        <location filename="../ui/number_box.cpp" line="31" />
        <source>must be finite (got %1)</source>
        <translation>muss endlich sein (erhalten: %1)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="33" />
        <source>must be between %1 and %2 (got %3)</source>
        <translation>muss zwischen %1 und %2 liegen (erhalten: %3)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="80" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::RunControls</name>
    <message>
        <location filename="../ui/run_controls.cpp" line="21" />
        <location filename="../ui/run_controls.cpp" line="72" />
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="73" />
        <source>Run or pause the simulation (Space)</source>
        <translation>Simulation starten oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="21" />
        <location filename="../ui/run_controls.cpp" line="72" />
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="74" />
        <source>&amp;Step</source>
        <translation>Sc&amp;hritt</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="75" />
        <source>Advance one time step (S)</source>
        <translation>Einen Zeitschritt weiter (S)</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="76" />
        <source>R&amp;eset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="77" />
        <source>Back to the scene's initial state (R)</source>
        <translation>Zurück zum Anfangszustand der Szene (R)</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="71" />
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="78" />
        <location filename="../ui/run_controls.cpp" line="79" />
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="80" />
        <source>Simulated seconds per real second</source>
        <translation>Simulierte Sekunden pro echter Sekunde</translation>
    </message>
</context>
<context>
    <name>carom::ui::SceneFiles</name>
    <message>
        <location filename="../ui/scene_files.cpp" line="29" />
        <source>Magic room</source>
        <translation>Magischer Raum</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="30" />
        <source>Galton board</source>
        <translation>Galtonbrett</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="31" />
        <source>Gas box</source>
        <translation>Gaskasten</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="32" />
        <source>Inelastic pile</source>
        <translation>Unelastischer Haufen</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="33" />
        <source>Newton's cradle</source>
        <translation>Newtons Wiege</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="34" />
        <source>Staircase</source>
        <translation>Treppe</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="35" />
        <source>Marble run</source>
        <translation>Murmelbahn</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="60" />
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="61" />
        <source>Carom scenes (*.carom *.json);;All files (*)</source>
        <translation>Carom-Szenen (*.carom *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="70" />
        <source>Cannot Open Scene</source>
        <translation>Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="114" />
        <source>“%1”</source>
        <translation>„%1“</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="115" />
        <source>an unsaved scene</source>
        <translation>eine ungespeicherte Szene</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="116" />
        <source>Recover Scene</source>
        <translation>Szene wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="117" />
        <source>Carom did not close properly while %1 had unsaved changes. The copy saved at %2 can be recovered.</source>
        <translation>Carom wurde nicht richtig beendet, während %1 ungespeicherte Änderungen hatte. Die um %2 gesicherte Kopie kann wiederhergestellt werden.</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="123" />
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="124" />
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="125" />
        <source>Not &amp;Now</source>
        <translation>&amp;Später</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="133" />
        <source>Cannot Recover Scene</source>
        <translation>Szene kann nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="157" />
        <source>Save Scene</source>
        <translation>Szene speichern</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="158" />
        <source>Carom scenes (*.carom);;All files (*)</source>
        <translation>Carom-Szenen (*.carom);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="169" />
        <source>Cannot Save Scene</source>
        <translation>Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="174" />
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="182" />
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="183" />
        <source>The scene %1 has unsaved changes. Save them?</source>
        <translation>Die Szene %1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>carom::ui::SimulationMenu</name>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="54" />
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="55" />
        <source>Speed vs &amp;Accuracy…</source>
        <translation>&amp;Geschwindigkeit und Genauigkeit…</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="56" />
        <source>&amp;Throw Speed Limit…</source>
        <translation>&amp;Wurfgeschwindigkeitsgrenze…</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="57" />
        <source>Timeline &amp;Memory…</source>
        <translation>Zeitleisten-S&amp;peicher…</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="58" />
        <source>&amp;Use Current State as Initial</source>
        <translation>Aktuellen Zustand als &amp;Anfang übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="59" />
        <source>Edits Apply to the &amp;Running State</source>
        <translation>Änderungen gelten für den &amp;laufenden Zustand</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="61" />
        <source>Off: an edit restarts the simulation from the edited scene. On: balls the edit leaves alone keep their running state.</source>
        <translation>Aus: Eine Änderung startet die Simulation mit der geänderten Szene neu. Ein: Kugeln, die die Änderung nicht betrifft, behalten ihren laufenden Zustand.</translation>
    </message>
</context>
<context>
    <name>carom::ui::SimulationSync</name>
    <message>
        <location filename="../ui/simulation_sync.cpp" line="73" />
        <source>The edit does not fit the running state (%1): restarted from the edited scene.</source>
        <translation>Die Änderung passt nicht zum laufenden Zustand (%1): Neustart mit der geänderten Szene.</translation>
    </message>
</context>
<context>
    <name>carom::ui::StatusReadout</name>
    <message numerus="yes">
        <location filename="../ui/status_readout.cpp" line="81" />
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %n balls   E = %5 J (drift %6)</source>
        <translation>
            <numerusform>t = %1 s   ×%2 Echtzeit   %3 fps   %4 Kollisionen/s   %n Kugel   E = %5 J (Drift %6)</numerusform>
            <numerusform>t = %1 s   ×%2 Echtzeit   %3 fps   %4 Kollisionen/s   %n Kugeln   E = %5 J (Drift %6)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/status_readout.cpp" line="89" />
        <source>   sound unavailable</source>
        <translation>   Ton nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../ui/status_readout.cpp" line="91" />
        <source>   muted</source>
        <translation>   stummgeschaltet</translation>
    </message>
    <message>
        <location filename="../ui/status_readout.cpp" line="92" />
        <source>   — the physics cannot keep up; running slower</source>
        <translation>   — die Physik kommt nicht hinterher; läuft langsamer</translation>
    </message>
</context>
<context>
    <name>carom::ui::TimelineBar</name>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="72" />
        <source>Timeline Memory</source>
        <translation>Speicher der Zeitleiste</translation>
    </message>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="72" />
        <source>Memory for the recorded run (MiB):</source>
        <translation>Speicher für den aufgezeichneten Lauf (MiB):</translation>
    </message>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="86" />
        <source>The recorded run: drag back to see an earlier moment; Run goes on from the moment shown and forgets what came after it.</source>
        <translation>Der aufgezeichnete Lauf: zurückziehen, um einen früheren Moment zu sehen; Starten setzt beim gezeigten Moment fort und vergisst, was danach kam.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/timeline_bar.cpp" line="98" />
        <source>t = %1 s · frame %2 of %3 · %4 MiB in %n keyframes</source>
        <translation>
            <numerusform>t = %1 s · Bild %2 von %3 · %4 MiB in %n Schlüsselbild</numerusform>
            <numerusform>t = %1 s · Bild %2 von %3 · %4 MiB in %n Schlüsselbildern</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="103" />
        <source>replayed in %1 ms</source>
        <translation>nachgespielt in %1 ms</translation>
    </message>
</context>
<context>
    <name>carom::ui::VideoExport</name>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="196" />
        <source>Start: must not be before 0 s (got %1 s)</source>
        <translation>Anfang: darf nicht vor 0 s liegen (erhalten: %1 s)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="198" />
        <source>End: must not be before the start, %1 s (got %2 s)</source>
        <translation>Ende: darf nicht vor dem Anfang (%1 s) liegen (erhalten: %2 s)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="201" />
        <source>End: the run is recorded up to %1 s only (got %2 s)</source>
        <translation>Ende: der Lauf ist nur bis %1 s aufgezeichnet (erhalten: %2 s)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="204" />
        <source>Frames per second: must be a whole number from %1 to %2 (got "%3")</source>
        <translation>Bilder pro Sekunde: muss eine ganze Zahl von %1 bis %2 sein (erhalten: „%3“)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="214" />
        <source>MP4 needs ffmpeg, which was not found on the PATH: choose PNG images, or install ffmpeg.</source>
        <translation>MP4 braucht ffmpeg, das im PATH nicht gefunden wurde: wählen Sie PNG-Bilder oder installieren Sie ffmpeg.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="219" />
        <source>MP4: the width and height must be even (got %1×%2)</source>
        <translation>MP4: Breite und Höhe müssen gerade sein (erhalten: %1×%2)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="255" />
        <location filename="../ui/dialogs/video_export.cpp" line="355" />
        <source>Export Video</source>
        <translation>Video exportieren</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="256" />
        <source>MP4 videos (*.mp4)</source>
        <translation>MP4-Videos (*.mp4)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="263" />
        <source>Export Video: Folder for the Frames</source>
        <translation>Video exportieren: Ordner für die Bilder</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="270" />
        <location filename="../ui/dialogs/video_export.cpp" line="478" />
        <source>Cannot Export Video</source>
        <translation>Video kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="281" />
        <source>A video is being exported already.</source>
        <translation>Es wird bereits ein Video exportiert.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="284" />
        <source>There is no run to export yet.</source>
        <translation>Es gibt noch keinen Lauf zum Exportieren.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="289" />
        <source>No folder or file was chosen.</source>
        <translation>Es wurde kein Ordner und keine Datei gewählt.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="292" />
        <source>Could not create the folder %1.</source>
        <translation>Der Ordner %1 konnte nicht angelegt werden.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="294" />
        <source>Could not write into the folder %1.</source>
        <translation>In den Ordner %1 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="297" />
        <source>The folder %1 already holds frames (frame_*.png): choose another folder or remove them first.</source>
        <translation>Der Ordner %1 enthält bereits Bilder (frame_*.png): wählen Sie einen anderen Ordner oder entfernen Sie sie zuerst.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="303" />
        <source>Could not write %1: its folder does not exist or cannot be written.</source>
        <translation>%1 konnte nicht geschrieben werden: der Ordner existiert nicht oder ist nicht beschreibbar.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="306" />
        <source>Could not write %1: it is a folder.</source>
        <translation>%1 konnte nicht geschrieben werden: es ist ein Ordner.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="343" />
        <source>Could not start ffmpeg: %1</source>
        <translation>ffmpeg konnte nicht gestartet werden: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="352" />
        <source>Exporting %n video frame(s)…</source>
        <translation>
            <numerusform>%n Videobild wird exportiert…</numerusform>
            <numerusform>%n Videobilder werden exportiert…</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="352" />
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="380" />
        <source>The run was reset or went on from an earlier frame during the export, which stopped after %n frame(s).</source>
        <translation>
            <numerusform>Der Lauf wurde während des Exports zurückgesetzt oder von einem früheren Bild aus fortgesetzt; der Export endete nach %n Bild.</numerusform>
            <numerusform>Der Lauf wurde während des Exports zurückgesetzt oder von einem früheren Bild aus fortgesetzt; der Export endete nach %n Bildern.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="400" />
        <source>Finishing the video…</source>
        <translation>Das Video wird fertiggestellt…</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="424" />
        <source>The graphics driver could not draw a %1×%2 picture.</source>
        <translation>Der Grafiktreiber konnte kein Bild mit %1×%2 Pixeln zeichnen.</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation type="vanished">%1 konnte nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="454" />
        <source>ffmpeg failed (exit code %1): %2</source>
        <translation>ffmpeg ist fehlgeschlagen (Exit-Code %1): %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="458" />
        <source>Exported %n video frame(s) of %1×%2 at %3 fps to %4</source>
        <translation>
            <numerusform>%n Videobild mit %1×%2 bei %3 fps nach %4 exportiert</numerusform>
            <numerusform>%n Videobilder mit %1×%2 bei %3 fps nach %4 exportiert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="472" />
        <source>The %n frame(s) written before were left in %1.</source>
        <translation>
            <numerusform>%n zuvor geschriebenes Bild bleibt in %1.</numerusform>
            <numerusform>Die %n zuvor geschriebenen Bilder bleiben in %1.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="490" />
        <source>Video export cancelled; the unfinished video was removed.</source>
        <translation>Videoexport abgebrochen; das unfertige Video wurde entfernt.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="491" />
        <source>Video export cancelled after %n frame(s); they were left in %1.</source>
        <translation>
            <numerusform>Videoexport nach %n Bild abgebrochen; es bleibt in %1.</numerusform>
            <numerusform>Videoexport nach %n Bildern abgebrochen; sie bleiben in %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>carom::ui::VideoExportDialog</name>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="79" />
        <source>Export Video</source>
        <translation>Video exportieren</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="91" />
        <source>PNG images in a folder</source>
        <translation>PNG-Bilder in einem Ordner</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="92" />
        <source>MP4 video (ffmpeg)</source>
        <translation>MP4-Video (ffmpeg)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="94" />
        <source>The run is recorded from 0 to %1 s. Each video frame shows the recorded step that ended at its moment or last before it.</source>
        <translation>Der Lauf ist von 0 bis %1 s aufgezeichnet. Jedes Videobild zeigt den aufgezeichneten Schritt, der zu seinem Zeitpunkt oder als letzter davor endete.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="106" />
        <source>MP4 needs ffmpeg, which was not found on the PATH (scripts/setup-debian.sh installs it); PNG images need nothing more.</source>
        <translation>MP4 braucht ffmpeg, das im PATH nicht gefunden wurde (scripts/setup-debian.sh installiert es); PNG-Bilder brauchen nichts weiter.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="116" />
        <source>Start (s)</source>
        <translation>Anfang (s)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="117" />
        <source>End (s)</source>
        <translation>Ende (s)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="118" />
        <source>Frames per second</source>
        <translation>Bilder pro Sekunde</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="119" />
        <source>Width (pixels)</source>
        <translation>Breite (Pixel)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="120" />
        <source>Height (pixels)</source>
        <translation>Höhe (Pixel)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="121" />
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="139" />
        <source>Start: must be a number of seconds (got "%1")</source>
        <translation>Anfang: muss eine Zahl von Sekunden sein (erhalten: „%1“)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="140" />
        <source>End: must be a number of seconds (got "%1")</source>
        <translation>Ende: muss eine Zahl von Sekunden sein (erhalten: „%1“)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="142" />
        <source>Frames per second: must be a whole number from %1 to %2 (got "%3")</source>
        <translation>Bilder pro Sekunde: muss eine ganze Zahl von %1 bis %2 sein (erhalten: „%3“)</translation>
    </message>
</context>
<context>
    <name>carom::ui::ViewMenu</name>
    <message>
        <location filename="../ui/view_menu.cpp" line="72" />
        <source>&amp;Full Screen</source>
        <translation>&amp;Vollbild</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="73" />
        <source>&amp;Explosions</source>
        <translation>&amp;Explosionen</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="74" />
        <source>&amp;Antialiasing</source>
        <translation>&amp;Kantenglättung</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="75" />
        <source>&amp;Mute</source>
        <translation>Stu&amp;mmschalten</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="71" />
        <source>F&amp;rame Scene</source>
        <translation>Szene ins &amp;Bild holen</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="70" />
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
</context>
<context>
    <name>carom::ui::WatchAlert</name>
    <message>
        <location filename="../ui/watch_alert.cpp" line="36" />
        <source>Stopped by the watch: %1</source>
        <translation>Von der Überwachung angehalten: %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_alert.cpp" line="51" />
        <source>Simulation Stopped</source>
        <translation>Simulation angehalten</translation>
    </message>
    <message>
        <location filename="../ui/watch_alert.cpp" line="55" />
        <source>The run is paused. The last step that passed the watch ended at %1 s. The checks and their tolerances are in Simulation &gt; Watch.</source>
        <translation>Der Lauf ist pausiert. Der letzte Schritt, der die Überwachung bestand, endete bei %1 s. Die Prüfungen und ihre Toleranzen stehen unter Simulation &gt; Überwachung.</translation>
    </message>
    <message>
        <location filename="../ui/watch_alert.cpp" line="62" />
        <source>Show the Moment Before</source>
        <translation>Den Moment davor zeigen</translation>
    </message>
</context>
<context>
    <name>carom::ui::WatchMenu</name>
    <message>
        <location filename="../ui/watch_menu.cpp" line="105" />
        <source>&amp;Watch</source>
        <translation>Ü&amp;berwachung</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="107" />
        <source>Stop on &amp;Non-finite Numbers</source>
        <translation>Bei &amp;nicht endlichen Zahlen anhalten</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="108" />
        <source>Stop on &amp;Energy Rise</source>
        <translation>Bei &amp;Energieanstieg anhalten</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="110" />
        <source>Only where no restitution exceeds 1, so that energy can only fall</source>
        <translation>Nur wenn keine Stoßzahl größer als 1 ist, sodass die Energie nur fallen kann</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="111" />
        <source>Stop on Escape Through a &amp;Solid</source>
        <translation>Bei Flucht durch einen &amp;Festkörper anhalten</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="112" />
        <source>Stop on Deep &amp;Penetration</source>
        <translation>Bei tiefem &amp;Eindringen anhalten</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="113" />
        <source>&amp;Tolerances…</source>
        <translation>&amp;Toleranzen…</translation>
    </message>
</context>
<context>
    <name>carom::ui::WatchToleranceDialog</name>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="15" />
        <source>Watch Tolerances</source>
        <translation>Toleranzen der Überwachung</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="27" />
        <source>Energy rise</source>
        <translation>Energieanstieg</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="29" />
        <source>How far the total energy may rise above its value at the start, as a fraction of the scene's energy scale (kinetic energy plus the balls' weight times the scene's height)</source>
        <translation>Wie weit die Gesamtenergie über ihren Anfangswert steigen darf, als Anteil der Energieskala der Szene (kinetische Energie plus Gewicht der Kugeln mal Höhe der Szene)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="32" />
        <source>Escape depth</source>
        <translation>Fluchttiefe</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="34" />
        <source>How far a ball's centre may be past a solid's surface, as a fraction of its radius</source>
        <translation>Wie weit der Mittelpunkt einer Kugel hinter der Oberfläche eines Festkörpers liegen darf, als Anteil ihres Radius</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="35" />
        <source>Penetration</source>
        <translation>Eindringtiefe</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="36" />
        <source>How deep an overlap may be, as a fraction of the smaller radius</source>
        <translation>Wie tief eine Überlappung sein darf, als Anteil des kleineren Radius</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="39" />
        <source>Energy rise:</source>
        <translation>Energieanstieg:</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="40" />
        <source>Escape depth:</source>
        <translation>Fluchttiefe:</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="41" />
        <source>Penetration:</source>
        <translation>Eindringtiefe:</translation>
    </message>
</context>
<context>
    <name>carom::ui::WorldToolBar</name>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="167" />
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="170" />
        <source>Gravity %1</source>
        <translation>Schwerkraft %1</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="171" />
        <source>Gravity %1 (m/s²)</source>
        <translation>Schwerkraft %1 (m/s²)</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="62" />
        <source>Change Gravity</source>
        <translation>Schwerkraft ändern</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="103" />
        <source>Change Accuracy</source>
        <translation>Genauigkeit ändern</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="173" />
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="174" />
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="175" />
        <source>Time step in seconds (+ and - keys)</source>
        <translation>Zeitschritt in Sekunden (Tasten + und -)</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="28" />
        <source>Change Time Step</source>
        <translation>Zeitschritt ändern</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="85" />
        <location filename="../ui/world_tool_bar.cpp" line="89" />
        <source>Change Method</source>
        <translation>Methode ändern</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="182" />
        <source>Integrator of the swept and discrete methods</source>
        <translation>Integrator der Methoden swept und discrete</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="35" />
        <source>Change Integrator</source>
        <translation>Integrator ändern</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="76" />
        <source>Auto: piloting the scene under 13 settings…</source>
        <translation>Auto: Vorlauf der Szene mit 13 Einstellungen …</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="166" />
        <source>World</source>
        <translation>Welt</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="154" />
        <source>Exact (event-driven), swept, or discrete steps; auto: the cheapest that meets the accuracy, found by a short pilot</source>
        <translation>Exakt (ereignisgesteuert), überstrichene oder diskrete Schritte; auto: die günstigste, die die Genauigkeit erreicht, per kurzem Vorlauf ermittelt</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="101" />
        <location filename="../ui/world_tool_bar.cpp" line="177" />
        <location filename="../ui/world_tool_bar.cpp" line="178" />
        <source>Accuracy</source>
        <translation>Genauigkeit</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="180" />
        <source>Auto's tolerance: the relative energy error per simulated second (and a penetration of at most 5% of the radius)</source>
        <translation>Toleranz von auto: der relative Energiefehler je simulierter Sekunde (und ein Eindringen von höchstens 5 % des Radius)</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="183" />
        <source>Larger Time Step</source>
        <translation>Größerer Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="184" />
        <source>Smaller Time Step</source>
        <translation>Kleinerer Zeitschritt</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/window_arguments.cpp" line="32" />
        <source>Collision physics sandbox</source>
        <translation>Sandbox für Kollisionsphysik</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="35" />
        <source>Scene file to open</source>
        <translation>Zu öffnende Szenendatei</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="38" />
        <source>Save a picture of the window and quit.</source>
        <translation>Ein Bild des Fensters speichern und beenden.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="39" />
        <source>file.png</source>
        <translation>datei.png</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="41" />
        <source>Run the simulation this long before --screenshot.</source>
        <translation>Die Simulation vor --screenshot so lange laufen lassen.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="42" />
        <source>seconds</source>
        <translation>Sekunden</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="43" />
        <source>Language of the program (en, ru, de).</source>
        <translation>Sprache des Programms (en, ru, de).</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="44" />
        <source>code</source>
        <translation>Code</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="46" />
        <source>Run a gas of N balls for 5 s with the view at 1280x720, print frame times and the longest GUI stall, and quit.</source>
        <translation>Ein Gas aus N Kugeln 5 s lang mit der Ansicht in 1280x720 laufen lassen, Bildzeiten und die längste Blockade der Oberfläche ausgeben und beenden.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="51" />
        <source>Run a gas at about 10,000 collisions a second with explosions and sound for S seconds, print the collision rate, frame rate, GUI stalls and memory every 10 s, and quit.</source>
        <translation>Ein Gas mit etwa 10.000 Stößen pro Sekunde S Sekunden lang mit Explosionen und Ton laufen lassen, alle 10 s Stoßrate, Bildrate, GUI-Blockaden und Speicher ausgeben und beenden.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="57" />
        <source>Open the scene file, run it for 5 s, select its last ball in the outline, print how long each took, and quit.</source>
        <translation>Die Szenendatei öffnen, 5 s laufen lassen, ihre letzte Kugel in der Gliederung auswählen, ausgeben, wie lange jeder Schritt dauerte, und beenden.</translation>
    </message>
</context>
</TS>
