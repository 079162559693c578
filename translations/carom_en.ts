<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<!-- English plural forms only: every other text is its own source. Kept by hand (lupdate would
     add every source text as unfinished); test_language checks "1 ball" and "2 balls". -->
<TS version="2.1" language="en_US">
<context>
    <name>carom::ui::StatusReadout</name>
    <message numerus="yes">
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %n balls   E = %5 J (drift %6)</source>
        <translation>
            <numerusform>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %n ball   E = %5 J (drift %6)</numerusform>
            <numerusform>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %n balls   E = %5 J (drift %6)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>carom::editor::PropertiesDock</name>
    <message numerus="yes">
        <source>%1: %n selected</source>
        <translation>
            <numerusform>%1: %n selected</numerusform>
            <numerusform>%1: %n selected</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n objects selected</source>
        <translation>
            <numerusform>%n object selected</numerusform>
            <numerusform>%n objects selected</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>carom::ui::AccuracyWindow</name>
    <message numerus="yes">
        <source>%Ln runs</source>
        <translation>
            <numerusform>%Ln run</numerusform>
            <numerusform>%Ln runs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%Ln threads</source>
        <translation>
            <numerusform>%Ln thread</numerusform>
            <numerusform>%Ln threads</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>carom::ui::TimelineBar</name>
    <message numerus="yes">
        <source>t = %1 s · frame %2 of %3 · %4 MiB in %n keyframes</source>
        <translation>
            <numerusform>t = %1 s · frame %2 of %3 · %4 MiB in %n keyframe</numerusform>
            <numerusform>t = %1 s · frame %2 of %3 · %4 MiB in %n keyframes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>carom::ui::VideoExport</name>
    <message numerus="yes">
        <source>Exporting %n video frame(s)…</source>
        <translation>
            <numerusform>Exporting %n video frame…</numerusform>
            <numerusform>Exporting %n video frames…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The run was reset or went on from an earlier frame during the export, which stopped after %n frame(s).</source>
        <translation>
            <numerusform>The run was reset or went on from an earlier frame during the export, which stopped after %n frame.</numerusform>
            <numerusform>The run was reset or went on from an earlier frame during the export, which stopped after %n frames.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Exported %n video frame(s) of %1×%2 at %3 fps to %4</source>
        <translation>
            <numerusform>Exported %n video frame of %1×%2 at %3 fps to %4</numerusform>
            <numerusform>Exported %n video frames of %1×%2 at %3 fps to %4</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The %n frame(s) written before were left in %1.</source>
        <translation>
            <numerusform>The %n frame written before was left in %1.</numerusform>
            <numerusform>The %n frames written before were left in %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Video export cancelled after %n frame(s); they were left in %1.</source>
        <translation>
            <numerusform>Video export cancelled after %n frame; it was left in %1.</numerusform>
            <numerusform>Video export cancelled after %n frames; they were left in %1.</numerusform>
        </translation>
    </message>
</context>
</TS>
