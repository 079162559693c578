<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>Language</name>
    <message>
        <location filename="../ui/language.cpp" line="16"/>
        <source>System Default</source>
        <translation>Systemstandard</translation>
    </message>
</context>
<context>
    <name>NumberText</name>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="31"/>
        <source>“%1” is out of range</source>
        <translation>„%1“ liegt außerhalb des Wertebereichs</translation>
    </message>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="33"/>
        <source>“%1” is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>ObjectRef</name>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="50"/>
        <source>Plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="51"/>
        <source>Cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="49"/>
        <source>Ball</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="53"/>
        <source>Planes</source>
        <translation>Ebenen</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="54"/>
        <source>Cylinders</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="52"/>
        <source>Balls</source>
        <translation>Kugeln</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="68"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::AccuracyWindow</name>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="39"/>
        <source>Speed vs accuracy</source>
        <translation>Geschwindigkeit und Genauigkeit</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="41"/>
        <source>Position error against exact (m)</source>
        <translation>Positionsfehler gegenüber exact (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="41"/>
        <source>Relative energy drift</source>
        <translation>Relative Energiedrift</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="42"/>
        <source>Deepest penetration (m)</source>
        <translation>Maximale Eindringtiefe (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="42"/>
        <source>Escaped balls</source>
        <translation>Entwichene Kugeln</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="48"/>
        <location filename="../ui/accuracy_window.cpp" line="71"/>
        <source>Computing time (s)</source>
        <translation>Rechenzeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="71"/>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="71"/>
        <source>Position error</source>
        <translation>Positionsfehler</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="72"/>
        <source>Energy drift</source>
        <translation>Energiedrift</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="72"/>
        <source>Penetration</source>
        <translation>Eindringtiefe</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="72"/>
        <source>Escaped</source>
        <translation>Entwichen</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="79"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="81"/>
        <source>Apply Selected Settings</source>
        <translation>Ausgewählte Einstellungen übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="88"/>
        <source>Each point is one run of the current scene; lower and further left is better. Choose a run to use its settings.</source>
        <translation>Jeder Punkt ist ein Lauf der aktuellen Szene; weiter unten und weiter links ist besser. Wählen Sie einen Lauf, um seine Einstellungen zu übernehmen.</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="95"/>
        <source>Error:</source>
        <translation>Fehler:</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditorTools</name>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="137"/>
        <source>Change Velocity</source>
        <translation>Geschwindigkeit ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="124"/>
        <source>Turn Plane</source>
        <translation>Ebene drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="130"/>
        <source>Turn Cylinder</source>
        <translation>Zylinder drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="226"/>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="277"/>
        <source>Click on a surface or on the ground to place an object.</source>
        <translation>Klicken Sie auf eine Fläche oder den Boden, um ein Objekt zu platzieren.</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="301"/>
        <source>Add Ball</source>
        <translation>Kugel hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="306"/>
        <source>No room for a ball there: %1</source>
        <translation>Dort ist kein Platz für eine Kugel: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="318"/>
        <source>Add Plane</source>
        <translation>Ebene hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="328"/>
        <source>Add Cylinder</source>
        <translation>Zylinder hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="331"/>
        <source>Cannot place it there: %1</source>
        <translation>Kann dort nicht platziert werden: %1</translation>
    </message>
</context>
<context>
    <name>carom::ui::EnergyPlot</name>
    <message>
        <location filename="../ui/energy_plot.cpp" line="35"/>
        <source>Kinetic</source>
        <translation>Kinetisch</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="36"/>
        <source>Potential</source>
        <translation>Potentiell</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="37"/>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="38"/>
        <source>Simulated time (s)</source>
        <translation>Simulierte Zeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="39"/>
        <source>Energy (J)</source>
        <translation>Energie (J)</translation>
    </message>
</context>
<context>
    <name>carom::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="80"/>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="151"/>
        <location filename="../ui/main_window.cpp" line="157"/>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="155"/>
        <source>Run or pause the simulation (Space)</source>
        <translation>Simulation starten oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="157"/>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="161"/>
        <source>&amp;Step</source>
        <translation>Sc&amp;hritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="163"/>
        <source>Advance one time step (S)</source>
        <translation>Einen Zeitschritt weiter (S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="169"/>
        <source>R&amp;eset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="171"/>
        <source>Back to the scene&apos;s initial state (R)</source>
        <translation>Zurück zum Anfangszustand der Szene (R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="177"/>
        <source>&amp;Full Screen</source>
        <translation>&amp;Vollbild</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="183"/>
        <source>&amp;Follow Ball</source>
        <translation>Kugel &amp;folgen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="189"/>
        <source>&amp;Explosions</source>
        <translation>&amp;Explosionen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="196"/>
        <source>&amp;Antialiasing</source>
        <translation>&amp;Kantenglättung</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="208"/>
        <source>&amp;Mute</source>
        <translation>Stu&amp;mmschalten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="213"/>
        <source>Larger Time Step</source>
        <translation>Größerer Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="216"/>
        <source>Smaller Time Step</source>
        <translation>Kleinerer Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="223"/>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="230"/>
        <location filename="../ui/main_window.cpp" line="231"/>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="232"/>
        <source>Simulated seconds per real second</source>
        <translation>Simulierte Sekunden pro echter Sekunde</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="240"/>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="243"/>
        <source>Gravity %1</source>
        <translation>Schwerkraft %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="245"/>
        <source>Gravity %1 (m/s²)</source>
        <translation>Schwerkraft %1 (m/s²)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="249"/>
        <source>Change Gravity</source>
        <translation>Schwerkraft ändern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="254"/>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="256"/>
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="257"/>
        <source>Time step in seconds (+ and - keys)</source>
        <translation>Zeitschritt in Sekunden (Tasten + und -)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="261"/>
        <source>Change Time Step</source>
        <translation>Zeitschritt ändern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="267"/>
        <source>Exact (event-driven), swept, or discrete steps</source>
        <translation>exact (ereignisgesteuert), swept oder discrete (feste Schritte)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="269"/>
        <source>Change Method</source>
        <translation>Methode ändern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="275"/>
        <source>Integrator of the swept and discrete methods</source>
        <translation>Integrator der Methoden swept und discrete</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="277"/>
        <source>Change Integrator</source>
        <translation>Integrator ändern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="284"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="286"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="293"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="300"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="303"/>
        <source>Speed vs &amp;Accuracy…</source>
        <translation>&amp;Geschwindigkeit und Genauigkeit…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="408"/>
        <source>The edit does not fit the running state (%1): restarted from the edited scene.</source>
        <translation>Die Änderung passt nicht zum laufenden Zustand (%1): Neustart mit der geänderten Szene.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="453"/>
        <source>Select</source>
        <translation>Auswählen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="454"/>
        <source>Add Ball</source>
        <translation>Kugel hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="455"/>
        <source>Add Plane</source>
        <translation>Ebene hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="456"/>
        <source>Add Cylinder</source>
        <translation>Zylinder hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="457"/>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="464"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="470"/>
        <source>Snap to &amp;Grid</source>
        <translation>Am &amp;Raster ausrichten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="473"/>
        <source>Moves land on multiples of %1 m</source>
        <translation>Verschiebungen landen auf Vielfachen von %1 m</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="482"/>
        <source>%1[*] — Carom</source>
        <translation>%1[*] — Carom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="508"/>
        <source>Apply Settings</source>
        <translation>Einstellungen übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="569"/>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="574"/>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="579"/>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="579"/>
        <source>Carom scenes (*.carom *.json);;All files (*)</source>
        <translation>Carom-Szenen (*.carom *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="582"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="585"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="596"/>
        <source>Cannot Open Scene</source>
        <translation>Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="607"/>
        <source>an unsaved scene</source>
        <translation>eine ungespeicherte Szene</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="609"/>
        <source>Recover Scene</source>
        <translation>Szene wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="610"/>
        <source>Carom did not close properly while %1 had unsaved changes. The copy saved at %2 can be recovered.</source>
        <translation>Carom wurde nicht richtig beendet, während %1 ungespeicherte Änderungen hatte. Die um %2 gesicherte Kopie kann wiederhergestellt werden.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="614"/>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="615"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="616"/>
        <source>Not &amp;Now</source>
        <translation>&amp;Später</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="623"/>
        <source>Cannot Recover Scene</source>
        <translation>Szene kann nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="643"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="646"/>
        <source>Save Scene</source>
        <translation>Szene speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="647"/>
        <source>Carom scenes (*.carom);;All files (*)</source>
        <translation>Carom-Szenen (*.carom);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="658"/>
        <source>Cannot Save Scene</source>
        <translation>Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="663"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="671"/>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="672"/>
        <source>The scene %1 has unsaved changes. Save them?</source>
        <translation>Die Szene %1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="706"/>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="727"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="729"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="733"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="736"/>
        <source>&amp;Paste</source>
        <translation>E&amp;infügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="739"/>
        <source>&amp;Duplicate</source>
        <translation>&amp;Duplizieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="742"/>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="744"/>
        <source>De&amp;lete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="747"/>
        <source>Select &amp;All</source>
        <translation>&amp;Alles auswählen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="757"/>
        <source>&amp;Use Current State as Initial</source>
        <translation>Aktuellen Zustand als &amp;Anfang übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="760"/>
        <source>Edits Apply to the &amp;Running State</source>
        <translation>Änderungen gelten für den &amp;laufenden Zustand</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="764"/>
        <source>Off: an edit restarts the simulation from the edited scene. On: balls the edit leaves alone keep their running state.</source>
        <translation>Aus: Eine Änderung startet die Simulation mit der geänderten Szene neu. Ein: Kugeln, die die Änderung nicht betrifft, behalten ihren laufenden Zustand.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="773"/>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="796"/>
        <source>clipboard</source>
        <translation>Zwischenablage</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="798"/>
        <source>Nothing to paste: %1</source>
        <translation>Nichts einzufügen: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="801"/>
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="825"/>
        <source>Cannot place the objects: %1</source>
        <translation>Die Objekte können nicht platziert werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="832"/>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="844"/>
        <source>Use Current State as Initial</source>
        <translation>Aktuellen Zustand als Anfang übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="291"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="307"/>
        <source>&amp;Examples</source>
        <translation>&amp;Beispiele</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="319"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="328"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="338"/>
        <source>The language changes when Carom is next started.</source>
        <translation>Die Sprache wird beim nächsten Start von Carom gewechselt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="549"/>
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %5 balls   E = %6 J (drift %7)</source>
        <translation>t = %1 s   ×%2 Echtzeit   %3 fps   %4 Kollisionen/s   %5 Kugeln   E = %6 J (Drift %7)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="559"/>
        <source>   sound unavailable</source>
        <translation>   Ton nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="561"/>
        <source>   muted</source>
        <translation>   stummgeschaltet</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="562"/>
        <source>   — the physics cannot keep up; running slower</source>
        <translation>   — die Physik kommt nicht hinterher; läuft langsamer</translation>
    </message>
</context>
<context>
    <name>carom::ui::NumberBox</name>
    <message>
        <location filename="../ui/number_box.cpp" line="35"/>
        <source>must be finite (got %1)</source>
        <translation>muss endlich sein (erhalten: %1)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="37"/>
        <source>must be between %1 and %2 (got %3)</source>
        <translation>muss zwischen %1 und %2 liegen (erhalten: %3)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="76"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::OutlineDock</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="143"/>
        <source>Outline</source>
        <translation>Übersicht</translation>
    </message>
</context>
<context>
    <name>carom::ui::OutlineModel</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="97"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="131"/>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
</context>
<context>
    <name>carom::ui::PropertiesDock</name>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="50"/>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="71"/>
        <source>(any length)</source>
        <translation>(beliebige Länge)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="72"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="72"/>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="76"/>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="77"/>
        <source>Choose a colour</source>
        <translation>Farbe wählen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80"/>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80"/>
        <source>Change Colour</source>
        <translation>Farbe ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="85"/>
        <location filename="../ui/editor/properties_dock.cpp" line="289"/>
        <source>default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="88"/>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="88"/>
        <location filename="../ui/editor/properties_dock.cpp" line="96"/>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="90"/>
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="90"/>
        <source>Change Velocity</source>
        <translation>Geschwindigkeit ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="92"/>
        <location filename="../ui/editor/properties_dock.cpp" line="106"/>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="92"/>
        <location filename="../ui/editor/properties_dock.cpp" line="106"/>
        <source>Change Radius</source>
        <translation>Radius ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="94"/>
        <source>Mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="94"/>
        <source>Change Mass</source>
        <translation>Masse ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="96"/>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101"/>
        <source>Normal</source>
        <translation>Normale</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101"/>
        <source>Turn Plane</source>
        <translation>Ebene drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="103"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="103"/>
        <source>Turn Cylinder</source>
        <translation>Zylinder drehen</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="109"/>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="109"/>
        <source>Change Gravity</source>
        <translation>Schwerkraft ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="111"/>
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="111"/>
        <source>Change Time Step</source>
        <translation>Zeitschritt ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="113"/>
        <location filename="../ui/editor/properties_dock.cpp" line="212"/>
        <source>Restitution</source>
        <translation>Stoßzahl</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="113"/>
        <location filename="../ui/editor/properties_dock.cpp" line="212"/>
        <source>Change Restitution</source>
        <translation>Stoßzahl ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="211"/>
        <source>0 to 1; empty: the world&apos;s restitution</source>
        <translation>0 bis 1; leer: die Stoßzahl der Welt</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="115"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="115"/>
        <source>Change Method</source>
        <translation>Methode ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="118"/>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="118"/>
        <source>Change Integrator</source>
        <translation>Integrator ändern</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="247"/>
        <source>World (nothing selected)</source>
        <translation>Welt (nichts ausgewählt)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="253"/>
        <location filename="../ui/editor/properties_dock.cpp" line="333"/>
        <location filename="../ui/editor/properties_dock.cpp" line="364"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="255"/>
        <source>%1: %n selected</source>
        <translation>
            <numerusform>%1: %n ausgewählt</numerusform>
            <numerusform>%1: %n ausgewählt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="258"/>
        <source>%n objects selected</source>
        <translation>
            <numerusform>%n Objekt ausgewählt</numerusform>
            <numerusform>%n Objekte ausgewählt</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="267"/>
        <source>mixed</source>
        <translation>verschieden</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="302"/>
        <source>world&apos;s (%1)</source>
        <translation>der Welt (%1)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="379"/>
        <source>Object Colour</source>
        <translation>Objektfarbe</translation>
    </message>
</context>
<context>
    <name>carom::ui::SceneDocument</name>
    <message>
        <location filename="../ui/editor/scene_document.cpp" line="55"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/carom_main.cpp" line="23"/>
        <source>Collision physics sandbox</source>
        <translation>Sandbox für Kollisionsphysik</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="26"/>
        <source>Scene file to open</source>
        <translation>Zu öffnende Szenendatei</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="29"/>
        <source>Save a picture of the window and quit.</source>
        <translation>Ein Bild des Fensters speichern und beenden.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="30"/>
        <source>file.png</source>
        <translation>datei.png</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="33"/>
        <source>Run the simulation this long before --screenshot.</source>
        <translation>Die Simulation vor --screenshot so lange laufen lassen.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="34"/>
        <source>seconds</source>
        <translation>Sekunden</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="36"/>
        <source>Language of the program (en, ru, de).</source>
        <translation>Sprache des Programms (en, ru, de).</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="37"/>
        <source>code</source>
        <translation>Code</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="40"/>
        <source>Run a gas of N balls for 5 s with the view at 1280x720, print frame times and the longest GUI stall, and quit.</source>
        <translation>Ein Gas aus N Kugeln 5 s lang mit der Ansicht in 1280x720 laufen lassen, Bildzeiten und die längste Blockade der Oberfläche ausgeben und beenden.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="46"/>
        <source>Run a gas at about 10,000 collisions a second with explosions and sound for S seconds, print the collision rate, frame rate, GUI stalls and memory every 10 s, and quit.</source>
        <translation>Ein Gas mit etwa 10.000 Stößen pro Sekunde S Sekunden lang mit Explosionen und Ton laufen lassen, alle 10 s Stoßrate, Bildrate, GUI-Blockaden und Speicher ausgeben und beenden.</translation>
    </message>
</context>
</TS>
