<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>FeatureDialog</name>
    <message numerus="yes">
        <source>Estimated time: %1 min %2 s, %n line(s)</source>
        <translation>
            <numerusform>Estimated time: %1 min %2 s, %n line</numerusform>
            <numerusform>Estimated time: %1 min %2 s, %n lines</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>GrblSettingsDialog</name>
    <message numerus="yes">
        <source>%n setting(s) backed up to %1</source>
        <translation>
            <numerusform>%n setting backed up to %1</numerusform>
            <numerusform>%n settings backed up to %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n setting(s) differ from the machine&apos;s; check them, then Send changes.</source>
        <translation>
            <numerusform>%1: %n setting differs from the machine&apos;s; check it, then Send changes.</numerusform>
            <numerusform>%1: %n settings differ from the machine&apos;s; check them, then Send changes.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>LoaderTexts</name>
    <message numerus="yes">
        <source>%1 does not look like G-code: nothing in it can be run (%n error(s); first, line %2: %3).</source>
        <translation>
            <numerusform>%1 does not look like G-code: nothing in it can be run (%n error; first, line %2: %3).</numerusform>
            <numerusform>%1 does not look like G-code: nothing in it can be run (%n errors; first, line %2: %3).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>OperatorActions</name>
    <message numerus="yes">
        <source>%1 has %n error(s) (first: line %2: %3). Fix them before running.</source>
        <translation>
            <numerusform>%1 has %n error (first: line %2: %3). Fix them before running.</numerusform>
            <numerusform>%1 has %n errors (first: line %2: %3). Fix them before running.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n line(s) in %2 s</source>
        <translation>
            <numerusform>Opened %1: %n line in %2 s</numerusform>
            <numerusform>Opened %1: %n lines in %2 s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n error(s); see the Problems list. It can be previewed but not run.</source>
        <translation>
            <numerusform>%1: %n error; see the Problems list. It can be previewed but not run.</numerusform>
            <numerusform>%1: %n errors; see the Problems list. It can be previewed but not run.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Preflight</name>
    <message numerus="yes">
        <source>(and %n more axis/direction(s))</source>
        <translation>
            <numerusform>(and %n more axis/direction)</numerusform>
            <numerusform>(and %n more axes/directions)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ProgramPanel</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Tool %1 is not in the tool table: edit the tool table…</source>
        <translation>
            <numerusform>Tool %1 is not in the tool table: edit the tool table…</numerusform>
            <numerusform>Tools %1 are not in the tool table: edit the tool table…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SessionBinder</name>
    <message numerus="yes">
        <source>saved as %1: %n line(s), verified by the card&apos;s CRC32</source>
        <translation>
            <numerusform>saved as %1: %n line, verified by the card&apos;s CRC32</numerusform>
            <numerusform>saved as %1: %n lines, verified by the card&apos;s CRC32</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SourceModel</name>
    <message numerus="yes">
        <source>%n move(s)</source>
        <translation>
            <numerusform>%n move</numerusform>
            <numerusform>%n moves</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… and %n more</numerusform>
            <numerusform>… and %n more</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Summary</name>
    <message numerus="yes">
        <source>%n line(s)</source>
        <translation>
            <numerusform>%n line</numerusform>
            <numerusform>%n lines</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n machine line(s)</source>
        <translation>
            <numerusform>%n machine line</numerusform>
            <numerusform>%n machine lines</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n move(s)</source>
        <translation>
            <numerusform>%n move</numerusform>
            <numerusform>%n moves</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
</context>
</TS>
