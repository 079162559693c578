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
    <name>carom::ui::AccuracyWindow</name>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="41"/>
        <source>Speed vs accuracy</source>
        <translation>Geschwindigkeit und Genauigkeit</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="43"/>
        <source>Position error against exact (m)</source>
        <translation>Positionsfehler gegenüber exact (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="43"/>
        <source>Relative energy drift</source>
        <translation>Relative Energiedrift</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="44"/>
        <source>Deepest penetration (m)</source>
        <translation>Maximale Eindringtiefe (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="44"/>
        <source>Escaped balls</source>
        <translation>Entwichene Kugeln</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="50"/>
        <location filename="../ui/accuracy_window.cpp" line="73"/>
        <source>Computing time (s)</source>
        <translation>Rechenzeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="73"/>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="73"/>
        <source>Position error</source>
        <translation>Positionsfehler</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="74"/>
        <source>Energy drift</source>
        <translation>Energiedrift</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="74"/>
        <source>Penetration</source>
        <translation>Eindringtiefe</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="74"/>
        <source>Escaped</source>
        <translation>Entwichen</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="81"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="83"/>
        <source>Apply Selected Settings</source>
        <translation>Ausgewählte Einstellungen übernehmen</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="90"/>
        <source>Each point is one run of the current scene; lower and further left is better. Choose a run to use its settings.</source>
        <translation>Jeder Punkt ist ein Lauf der aktuellen Szene; weiter unten und weiter links ist besser. Wählen Sie einen Lauf, um seine Einstellungen zu übernehmen.</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="97"/>
        <source>Error:</source>
        <translation>Fehler:</translation>
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
        <location filename="../ui/main_window.cpp" line="53"/>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="94"/>
        <location filename="../ui/main_window.cpp" line="99"/>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="97"/>
        <source>Run or pause the simulation (Space)</source>
        <translation>Simulation starten oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="99"/>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="103"/>
        <source>&amp;Step</source>
        <translation>Sc&amp;hritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="105"/>
        <source>Advance one time step (S)</source>
        <translation>Einen Zeitschritt weiter (S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="111"/>
        <source>R&amp;eset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="113"/>
        <source>Back to the scene&apos;s initial state (R)</source>
        <translation>Zurück zum Anfangszustand der Szene (R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="119"/>
        <source>&amp;Full Screen</source>
        <translation>&amp;Vollbild</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="125"/>
        <source>&amp;Follow Ball</source>
        <translation>Kugel &amp;folgen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="131"/>
        <source>&amp;Explosions</source>
        <translation>&amp;Explosionen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="138"/>
        <source>&amp;Antialiasing</source>
        <translation>&amp;Kantenglättung</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="150"/>
        <source>&amp;Mute</source>
        <translation>Stu&amp;mmschalten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="155"/>
        <source>Larger Time Step</source>
        <translation>Größerer Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="158"/>
        <source>Smaller Time Step</source>
        <translation>Kleinerer Zeitschritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="165"/>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="172"/>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="173"/>
        <source>Simulated seconds per real second</source>
        <translation>Simulierte Sekunden pro echter Sekunde</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="180"/>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="183"/>
        <source>Gravity %1 (m/s²)</source>
        <translation>Schwerkraft %1 (m/s²)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="189"/>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="190"/>
        <source>Time step in seconds (+ and - keys)</source>
        <translation>Zeitschritt in Sekunden (Tasten + und -)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="198"/>
        <source>Exact (event-driven), swept, or discrete steps</source>
        <translation>exact (ereignisgesteuert), swept oder discrete (feste Schritte)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="205"/>
        <source>Integrator of the swept and discrete methods</source>
        <translation>Integrator der Methoden swept und discrete</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="212"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="215"/>
        <source>Speed vs &amp;Accuracy…</source>
        <translation>&amp;Geschwindigkeit und Genauigkeit…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="217"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="219"/>
        <source>&amp;Examples</source>
        <translation>&amp;Beispiele</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="230"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="236"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="246"/>
        <source>The language changes when Carom is next started.</source>
        <translation>Die Sprache wird beim nächsten Start von Carom gewechselt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="254"/>
        <source>%1 — Carom</source>
        <translation>%1 — Carom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="334"/>
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %5 balls   E = %6 J (drift %7)</source>
        <translation>t = %1 s   ×%2 Echtzeit   %3 fps   %4 Kollisionen/s   %5 Kugeln   E = %6 J (Drift %7)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="344"/>
        <source>   sound unavailable</source>
        <translation>   Ton nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="346"/>
        <source>   muted</source>
        <translation>   stummgeschaltet</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="347"/>
        <source>   — the physics cannot keep up; running slower</source>
        <translation>   — die Physik kommt nicht hinterher; läuft langsamer</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/carom_main.cpp" line="125"/>
        <source>Collision physics sandbox</source>
        <translation>Sandbox für Kollisionsphysik</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="128"/>
        <source>Scene file to open</source>
        <translation>Zu öffnende Szenendatei</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="131"/>
        <source>Save a picture of the window and quit.</source>
        <translation>Ein Bild des Fensters speichern und beenden.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="132"/>
        <source>file.png</source>
        <translation>datei.png</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="135"/>
        <source>Run the simulation this long before --screenshot.</source>
        <translation>Die Simulation vor --screenshot so lange laufen lassen.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="136"/>
        <source>seconds</source>
        <translation>Sekunden</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="138"/>
        <source>Language of the program (en, ru, de).</source>
        <translation>Sprache des Programms (en, ru, de).</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="139"/>
        <source>code</source>
        <translation>Code</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="142"/>
        <source>Run a gas of N balls for 5 s with the view at 1280x720, print frame times and the longest GUI stall, and quit.</source>
        <translation>Ein Gas aus N Kugeln 5 s lang mit der Ansicht in 1280x720 laufen lassen, Bildzeiten und die längste Blockade der Oberfläche ausgeben und beenden.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="168"/>
        <source>Cannot open scene</source>
        <translation>Szene kann nicht geöffnet werden</translation>
    </message>
</context>
</TS>
