<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>ConnectionBar</name>
    <message>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>link %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ConsoleView</name>
    <message>
        <source>filter (text)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frames sent to the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frames received from the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stream/status frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pause scrolling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MDI: a G-code line (G0 X10) or a command (HOME, SD LIST, GET KP_X)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>resends %1 (%2 %)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>DiagnosticsView</name>
    <message>
        <source>%1 error mm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>JobStatusBar</name>
    <message>
        <source>machine position in work coordinates (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1/%2 · elapsed %3 · remaining %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>JogPanel</name>
    <message>
        <source>Jog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog one axis by the chosen step at the feed beside it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm/min</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LinkAlert</name>
    <message>
        <source>The USB link between this computer and the machine is lost: no valid frame for 3 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine&apos;s internal link (UART between the main board and the motion board) is lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine carries on with the job from its SD card.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine holds the job on the path (feed hold), spindle as it was: it has not lost its place.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No job was running; the machine stays where it is.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home and restart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abandon job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>⚠ Link to the machine lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the cable and the machine&apos;s power, then reconnect.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>✓ Link restored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine kept its position. Resume the job at line %1 of %2: no line runs twice, none is skipped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine was reset and no longer knows its position. Home it, check the stock, then restart at line %1 of %2 with the feed and spindle restored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine answers again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LinkState</name>
    <message>
        <source>connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>degraded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Loader</name>
    <message>
        <source>%1 could not be loaded: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 could not be read as G-code: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 does not exist (moved or deleted?).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be opened: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a G-code file (it holds binary data, such as an image).</source>
        <translation type="unfinished"></translation>
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
    <name>MachineCodes</name>
    <message>
        <source>a limit switch was hit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>following error: an axis fell behind its path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine lost the computer link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the link between the machine&apos;s two boards is lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine (re)started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine is not homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the move would leave the travel (soft limit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine cannot read this line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a value is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no feed rate (F) given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the arc is not valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the line number is out of order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine is busy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the cover is open: no motion allowed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine is in alarm: home it after a fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine&apos;s queue is full</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wrong arguments for the command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no such setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine does not know this command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file name is not allowed on the card</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no such file on the card</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the SD card is full</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file on the card does not match (CRC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %1 in the %2 direction: %3 mm is past the limit %4 mm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MachineControls</name>
    <message>
        <source>Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home (recover)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>after a fault: first move away from the switches, then home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed hold, at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop and flush, at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check mode (dry run, no motion)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> rpm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Work zero (here)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured —</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured %1 rpm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MachineFlags</name>
    <message>
        <source>homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cover open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>host lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UART lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SD</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MachinePanelView</name>
    <message>
        <source>Cover open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the cover switch: while open the machine refuses every motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine&apos;s 128 x 64 OLED (its 5x7 font is ASCII only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MRESET: resets the main board; RESET: the motion board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no machine panel (connect to the built-in simulator)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LED</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>buzzer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>buzzer off</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MachineState</name>
    <message>
        <source>IDLE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RUN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HOLD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>JOG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine controls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SD card</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Console</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC mill controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagnostics (commanded vs measured)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Menus</name>
    <message>
        <source>G-code (*.ngc *.nc *.gcode *.gc *.tap *.cnc *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save to SD card…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save screens&amp;hot…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Se&amp;ttings…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect / disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home after a &amp;fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pause (feed hold)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R&amp;esume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop and flush at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Jog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step 0.1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step 1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step 10 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle o&amp;n</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle o&amp;ff</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set work zero X&amp;Y here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set work zero &amp;Z here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check mode (&amp;dry run)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fit program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Dark palette</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operator &amp;guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open G-code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operator guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;CNC mill controller&lt;/b&gt;&lt;br&gt;A desktop controller for a small 3-axis mill: G-code preview, SD upload, streaming over a checked frame protocol with resume after a link loss, and a simulator of the machine.&lt;br&gt;PySide6 + pyqtgraph. MIT licence.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1. Connect (the built-in simulator is first in the port list).
2. File ▸ Open (or drop a file on the window); check the preview and the Problems list.
3. Optionally save the program to the SD card (SD card dock).
4. Home (Ctrl+H), then Start (Ctrl+R). Pause Ctrl+P, Resume Ctrl+Shift+P, Stop Esc.
5. Jog with Ctrl+arrows (X/Y) and Ctrl+PgUp/PgDn (Z); step Alt+1/2/3.
If the link drops, the machine holds; reconnect and resume from the alert.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>OperatorActions</name>
    <message>
        <source>Reconnecting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a G-code file first (File ▸ Open…).</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 has %n error(s) (first: line %2: %3). Fix them before running.</source>
        <translation>
            <numerusform>%1 has %n error (first: line %2: %3). Fix them before running.</numerusform>
            <numerusform>%1 has %n errors (first: line %2: %3). Fix them before running.</numerusform>
        </translation>
    </message>
    <message>
        <source>Program has errors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home the machine before starting a job (Machine ▸ Home).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing first; press “Home and restart” again once homed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a G-code file to save it to the card.</source>
        <translation type="unfinished"></translation>
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
    <message>
        <source>Settings not saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write the settings file: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings saved and sent to the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings saved</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Ports</name>
    <message>
        <source>Built-in simulator (sim://)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PositionPlot</name>
    <message>
        <source>time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PreviewWidget</name>
    <message>
        <source>wheel: zoom · drag: pan · Ctrl+F: fit · Ctrl+G: grid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rapid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed Z ≥ 0</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProgramPanel</name>
    <message>
        <source>Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Col</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No program open. File ▸ Open… or drop a G-code file on the window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Problems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No program open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… and %n more</numerusform>
            <numerusform>… and %n more</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation type="unfinished"></translation>
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
    <message>
        <source>Problems (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>warning</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <source>Look in:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>List View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QMessageBox</name>
    <message>
        <source>About Qt</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show Details...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hide Details...</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SdPanel</name>
    <message>
        <source>a card name has 1 to 32 letters, digits, &apos;_&apos;, &apos;-&apos; or &apos;.&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>name on the card</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save program to SD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>send the open program to the card; the machine checks every line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run from SD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine runs the file on its own, even without this computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uploading…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SessionBinder</name>
    <message>
        <source>Open failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The port could not be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the port failed; details in the console</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The serial port reported an error; the details are in the console.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 % resends</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine alarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>saved as %1: %n line(s), verified by the card&apos;s CRC32</source>
        <translation>
            <numerusform>saved as %1: %n line, verified by the card&apos;s CRC32</numerusform>
            <numerusform>saved as %1: %n lines, verified by the card&apos;s CRC32</numerusform>
        </translation>
    </message>
    <message>
        <source>not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Job finished</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Job ended</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The job did not complete: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine refused</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SettingsDialog</name>
    <message>
        <source>PID gains</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feeds &amp;&amp; motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link &amp;&amp; heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Travel &amp;&amp; offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the window&apos;s language; it changes at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PID gains are pushed to the machine (SET) when you press OK while connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>range %1 … %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SettingsFields</name>
    <message>
        <source>supply voltage (V)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bridge drop (V)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no-load speed (rpm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gear ratio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>encoder pulses per turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>quadrature edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>screw lead (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X travel (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y travel (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z travel (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>home back-off (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>work offset X (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>work offset Y (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>work offset Z (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rapid feed (mm/min)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>maximum feed (mm/min)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acceleration (mm/s²)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>jerk (mm/s³)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>junction deviation (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>arc tolerance (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>homing feed (mm/min)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kp (proportional)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ki (integral)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kd (derivative)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control loop rate (Hz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>following error limit (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>heartbeat period (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>degraded after (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lost after (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>motor supply voltage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>voltage lost in the L298N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output shaft rpm unloaded at supply_v</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>motor turns per output turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pulses per motor turn per channel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edges counted per pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lead screw travel per output turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>back-off from each switch after homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>default work offset X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>default work offset Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>default work offset Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G00 feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cap on programmed feeds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chord error when arcs become lines</source>
        <translation type="unfinished"></translation>
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
    <message>
        <source>%1 → %2, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cut %1 mm, rapid %2 mm, estimated %3</source>
        <translation type="unfinished"></translation>
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
    <message>
        <source>%1, %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
