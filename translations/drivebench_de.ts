<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QObject</name>
    <message>
        <source>Esc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>window deactivated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not ready to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault reaction active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interpolated position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cyclic sync position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cyclic sync velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cyclic sync torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manufacturer mode %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode %1</source>
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
    <message>
        <source>connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>closing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restore: %1 verified, %2 written, %3 failed, %4 mismatch, %5 skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stored to non-volatile memory (1010h sub 1 = &quot;save&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cli</name>
    <message>
        <source>drivebench command line: read and write drive objects from scripts.

Commands:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>

Exit codes: 0 ok, 1 failure, 2 usage, 3 connection, 4 timeout, 5 malformed answer, 6 device error, 128 + N stopped by signal N (record: 130 Ctrl-C, 143 SIGTERM).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time limit per request in ms (default 1000).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time limit for connecting in ms (default 3000).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print integers in hex.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data type of an object the device description does not know (u8, i16, u32, REAL32, ...).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name what is printed and log the traffic on stderr.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read/write: the value as raw bytes to/from this file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dcf: the file to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CANopen SDO mode: auto (default), expedited, segmented, block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nmt: every node (broadcast).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language of the messages: de or en (default: DRIVEBENCH_LANG, else LC_ALL, LC_MESSAGES, LANG).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What to do (see above).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>drivebench-cli: --lang takes one of: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::ParameterBackup</name>
    <message>
        <source>no connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>backup cancelled after %1 of %2 objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the backup has not finished</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no object could be read (first: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing to read: no readable object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no object could be read (%1 tried; first: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 objects could not be read (first: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the connection was closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device stopped answering; reading %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device answered an identity that is not a UNSIGNED32: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device answered a value that is not a %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::ParameterRestore</name>
    <message>
        <source>not in the device description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing to restore: the parameter set holds no object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing to restore: no selected object is in the set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restore cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the connection was closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>write-only: not read back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled before the read-back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO %1h not changed: reading its COB-ID failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mapping not changed: reading %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO %1h could not be disabled: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mapping %1 could not be cleared: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing back the previous value of %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>written, but the read-back failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading back %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read back %1, expected %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>not stored: %n row(s) did not succeed</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>storing (1010h sub 1 = &quot;save&quot;) failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not stored: the restore stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not attempted: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO %1h left disabled (COB-ID bit 31 set)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::app</name>
    <message>
        <source>MovingCap RefGo (ASCII over TCP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CANopen over SLCAN in TCP (MovingCap ETH: node 50)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CANopen over Qt CAN plugin &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::cli</name>
    <message>
        <source>move: absolute target (user units).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move: distance from the actual position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move: distance from the last target (MC_MoveAdditive).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move, jog, home: velocity (units/s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move, jog, home: acceleration (units/s²).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move, jog: deceleration (units/s²).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>jog: how long to jog (ms).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>motion commands: longest wait for the end (ms, default 60000).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::gui::MainWindow</name>
    <message>
        <source>drivebench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scope</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object Access</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CANopen Nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN Monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Morse IP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
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
        <source>&amp;About drivebench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot connect to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Removed %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About drivebench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;drivebench %1&lt;/h3&gt;&lt;p&gt;Commissioning tool for industrial drives.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connection closed by the user</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object Dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter Sets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Parameters</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::morseio::CameraSource</name>
    <message>
        <source>Camera &quot;%1&quot; delivers no frames after %2 s (in use by another program, or no permission for its device?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No camera found (Qt Multimedia lists none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot be opened (busy or no permission?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting camera &quot;%1&quot;…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region %1,%2 %3x%4 lies outside the %5x%6 camera frame; searching for the blinking LED automatically</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot; was disconnected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera frames cannot be read (pixel format %1, %2x%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Searching for the blinking LED…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LED at %1,%2 (%3x%4 px)%5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, your region</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LED lost (no blinking for %1 s): searching again…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope</name>
    <message>
        <source>cannot read the PDO configuration: not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDOs need a connection to a CANopen node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the PDO configuration of node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no event timer and is sent only on device events</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is sent on SYNC (transmission type %2) and no SYNC was produced</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is sent only on events or remote requests (type 0x%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 is operational (heartbeat), yet its TPDOs did not come</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 is operational (heartbeat), but %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 is pre-operational (heartbeat), not operational: NMT start it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 is stopped (heartbeat), not operational: NMT start it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 is probably not operational (no heartbeat heard): NMT start it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; or %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; or </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TPDO number out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TPDO%1 has no predefined COB-ID; give one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node id must be 1..127</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>event timer must be 0..65535 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no objects to map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a numeric object of the description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the objects need %1 bits; a PDO carries at most 64</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no PDO client</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>trigger &apos;%1&apos;: %2 (expected CHANNEL,rising|falling|above|below,LEVEL or CHANNEL,inside|outside,LOW,HIGH or CHANNEL,bitN,set|clear)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope::PdoChannelPlan</name>
    <message>
        <source>%1 is in no TPDO of node %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope::PdoSource</name>
    <message>
        <source>cannot add a channel while sampling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: only numeric types can be sampled from a PDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: bytes %2..%3 do not fit into a CAN frame of 8 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: bad COB-ID or period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not enabled (COB-ID bit 31 set)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot sample PDOs: the CAN bus is not open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO sampling stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO sampling stopped: the CAN bus was closed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope::PollingSource</name>
    <message>
        <source>the connection was closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no connection to poll</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot add a channel while sampling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the sample period must be &gt;= 0 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2) is write-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2) is not a number and cannot be recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot sample %1: not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the answer is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sampling stopped</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope::Recorder</name>
    <message>
        <source>no channels to record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>single and normal mode need a trigger on a recorded channel with pre/post times &gt;= 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>channel %1 has no source (loaded from a file or its source was closed)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope::Trigger</name>
    <message>
        <source>missing condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not one of the recorded channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bit number must be 0..63</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a bit trigger ends in &apos;set&apos; or &apos;clear&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>&apos;%1&apos; takes %n number(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>window low bound above the high bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown condition &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope::analysis</name>
    <message>
        <source>a spectrum needs at least %1 samples in the range (has %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the samples in the range have no time spacing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the range is too short for a spectrum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a step response needs at least 3 samples in the range (has %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no step in the range (initial and final value are equal)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the signal does not rise from 10 % to 90 % of the step in the range</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::scope::csv</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bad trigger detail &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a drivebench recording (the first line must be &apos;# drivebench recording v1&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bad start time &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>channel line without a valid &apos;INDEX:SUB&apos; id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>channel %1: bad scale or offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bad gap time &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no &apos;# channel:&apos; lines before the data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing the column header &apos;time_s,...&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cells, expected %2 (time and one per channel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a time in seconds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time goes back (%1 s after a later row)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>column %1 (%2): &apos;%3&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::CanMonitor</name>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Freeze the table; frames are still captured and appear when you resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forget every frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the frames shown as a candump log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autoscroll</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>580-5FF, 81-FF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>COB-IDs in hex: single ids and ranges, comma separated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RX + TX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>6041</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object index (hex), optionally :sub-index: SDO traffic of this object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>4B 41 60 ?? 27</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data from byte 0 in hex; ?? matches any byte, ? any digit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search decoded text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Text in the service or the CANopen reading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object index (hex), optionally :sub-index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 oldest dropped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — paused, %1 waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — no CAN bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save CAN log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>candump logs (*.log);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::CanMonitorModel</name>
    <message>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dir</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Len</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Service</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CANopen</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ConnectionDialog</name>
    <message>
        <source>Connect to Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IP address, host name or CAN interface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e.g. node=50&amp;bitrate=500000</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme://host[:port][?key=value]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P&amp;ort:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>O&amp;ptions:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;URI:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recent connections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter an address or a connection URI.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connects to %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::DeviceList</name>
    <message>
        <source>Add…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a new connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect the selected device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect the selected device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close and remove the selected device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
State: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
Last error: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::DriveStatusPanel</name>
    <message>
        <source>Not ready to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault reaction active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n read(s) failed; %1: %2</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Updated %1, every %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No error or warning bits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Internal limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Statusword:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position (6064h):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity (606Ch):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current (6078h):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>603Fh keeps the last error after it has been cleared.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status register (1002h):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last error (603Fh):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Digital I/O</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs (60FDh):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IN%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs (60FEh.1):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OUT%1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::JogPanel</name>
    <message>
        <source>jog button released</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the panel let go of the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deadman watchdog: the GUI stopped refreshing for %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connection lost (%1); the drive may still be moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>focus left the jog panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Esc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>jog key released</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>window deactivated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>jog panel hidden</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog and step move in leases of %1 ms plus the braking distance: the drive stops by itself when the renewals stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No drive-side supervision on this connection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Active: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On enable: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Powered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Referenced</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limit −</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limit +</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog (hold to run; keys ← → or − +)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>◀ Jog −</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog + ▶</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step −</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step +</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accel.:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Override:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not read yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the limits…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Software limits (607Dh): the full 32-bit range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Software limits (607Dh): %1 … %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Software limits (607Dh): none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max velocity: %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max velocity: not given by the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max acceleration: %1 %2/s²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max acceleration: not given by the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position window: %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::LogConsole</name>
    <message>
        <source>Connection events and warnings appear here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show Protocol Traffic</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::MorsePanel</name>
    <message>
        <source>Open video or CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LED frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IP: –</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MovingCap RefGo (refgo://IP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CANopen over SLCAN (canopen+slcan://IP?node=50)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>brightness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>threshold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dah</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a video of the LED or a CSV of samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Videos and CSV (*.mp4 *.mov *.avi *.mkv *.webm *.3gp *.csv *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No file reader in this build.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IP: %1  (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IP: %1  (partly read)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for the blinking LED…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a video of the green STATUS LED (at least two message repetitions) or a CSV of samples, or start a camera.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confident: %1 agreeing messages, unit %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decoding… </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(CSV: no frame)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No camera input in this build</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No camera found (Qt Multimedia lists none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Film the green STATUS LED: it is found automatically, or drag a rectangle around it on the frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot; (stopped)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot;: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::MotionForm</name>
    <message>
        <source>idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>busy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Optimised</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Positive only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Negative only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bewegungsrichtung: used by MC_MoveAbsolute on an endless axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ‰ rated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jerk:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accel.:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decel.:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Torque:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Execute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Halt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MC_Halt: brake with the deceleration; a new command may follow at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MC_Stop: brake with the deceleration; other commands are refused until standstill</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No command yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>35: set current position as zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This drive has no torque mode: the command will be refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive has no jerk object; the jerk field only satisfies the command rules.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (target %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity limited to the maximum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>override clamped at the maximum velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acceleration or jerk limited</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::NodeList</name>
    <message>
        <source>All nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send NMT commands to every node (node id 0)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::NodeListModel</name>
    <message>
        <source>lost (was %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown (sent %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>never</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s ago</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The node of this connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ObjectAccessBox</name>
    <message>
        <source>He&amp;x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>auto (integer)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data type for objects the device description does not know</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter an object address, e.g. 6041:0 or 6064</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;br&gt;%1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, unit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not in the device description; it is read as an integer, or as the type you pick.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This object is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>written %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::OdBitFieldView</name>
    <message>
        <source>Select an object to see its details.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, storable</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::OdEditor</name>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>He&amp;x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter by index, name or value (e.g. 6041, velocity)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live refresh of the rows on screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read every object of the device once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>By index…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read or write an object the device description does not list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 not written: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing %1 %2…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n object(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>filter: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read/Write by Index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Objects that the device description does not list are added to the tree once read or written.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::OdEditorModel</name>
    <message>
        <source>Communication (1000h–1FFFh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manufacturer (2000h–5FFFh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device profile (6000h–9FFFh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not in the description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Index:Sub</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Access</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min … Max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(write-only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ParamCompareModel</name>
    <message>
        <source>Not restorable: the file has no value, or the object is read-only or unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Index:Sub</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ParamCompareReport</name>
    <message>
        <source>Restore Report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore Report — Incomplete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 written&lt;/b&gt; (%2 verified by reading back), &lt;b&gt;%3 failed&lt;/b&gt;, %4 mismatched, %5 skipped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stored permanently (1010h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not stored permanently: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Index:Sub</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reason</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Copy Report</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ParamCompareView</name>
    <message>
        <source>Only &amp;differences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status includes d&amp;efaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>He&amp;x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Load Set…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-read &amp;Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select Differences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store permanently afterwards (1010h)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Restore Selected…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off: the status compares device and file only. On: a row also counts as changed or missing when the defaults differ.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After every row was written and verified, write &quot;save&quot; to 1010h so the values survive a power cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No parameter set loaded. &lt;i&gt;Load Set…&lt;/i&gt; reads a file made by &lt;i&gt;Back Up…&lt;/i&gt; or &lt;code&gt;drivebench-cli backup&lt;/code&gt;; nothing is written to the device until you restore.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load Parameter Set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter sets (*.dbp *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot load %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%1&lt;/b&gt; — %2 %3, %n object(s), saved %4 from %5</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Loaded %1. Nothing has been written to the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Restore Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Write %n selected value(s) from %1 to %2?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Afterwards the values are stored permanently (1010h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The values are not stored permanently; they are lost at the next power cycle unless you store them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected: the device column stays empty until a device is connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Reading %n object(s) from the device…</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Reading the device failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The comparison shows the device after the restore.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compared %1 with the device. Nothing has been written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Compared; %n object(s) could not be read: %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Writing %n value(s)…</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Restored %n value(s)%1.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source> and stored them permanently</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore incomplete: %1 written, %2 failed, %3 skipped (see the report).</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>&amp;Restore %n Selected…</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>db::widgets::ParameterSetActions</name>
    <message>
        <source>&amp;Back Up…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Compare / Restore…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Store Permanently</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore &amp;Factory Defaults…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;DCF…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save every storable parameter of the device to a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load a parameter set and compare it with the device and the defaults; restore selected rows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the device&apos;s current parameters in its non-volatile memory (1010h &quot;save&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset every parameter to the factory value (1011h &quot;load&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write a CiA 306 device configuration file with the device&apos;s current values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back Up Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter sets (*.dbp);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backing up parameters…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>partial backup: %1 of %2 objects could not be read; not a complete set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup incomplete, %1 not written: %2
%3
Failed: %4%5</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The %n parameter(s) read and the failures are in %1.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> and %n more</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Backup not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Backed up %n parameter(s) to %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Export DCF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device configuration files (*.dcf);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading parameters for the DCF…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCF not written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Exported the DCF with %n value(s) to %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backup cancelled; nothing was saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store the current parameters of %1 permanently (1010h &quot;save&quot;)?

The values the device holds now become its power-up values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameters stored permanently</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Factory defaults restored (1011h); they take effect after the next reset or power cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused by the device: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every parameter of %1 returns to its factory value: positions, limits, velocities, I/O functions, PDO mappings and communication settings you changed are lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On a MovingCap this also deletes the Python script stored in the drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore Factory Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore the factory defaults (1011h &quot;load&quot;)?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This cannot be undone from drivebench unless you have a backup.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back Up First…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore Defaults Without Backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back Up Before Factory Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Factory defaults not restored: the backup did not succeed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopeAnalysisDialog</name>
    <message>
        <source>Analysis: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; from %2 s to %3 s (%4 samples)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Figures</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frequency (Hz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>amplitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>amplitude [%1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No spectrum: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RMS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Std. deviation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min / max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak-peak</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spectral peak</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sample period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step response</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rise time (10–90 %)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 after the step start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settling time (2 %)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopeChannelModel</name>
    <message>
        <source>Channel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 [%2]
device: %3
display = raw × %4 + %5
%6 samples, %7 lost
double-click the name to change the colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopeMeasurements</name>
    <message>
        <source>Channel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B − A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RMS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P-P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dy: value at B minus value at A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>peak-to-peak between A and B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cursors off: switch them on to measure between A and B.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;A&lt;/b&gt; %1 s &amp;nbsp; &lt;b&gt;B&lt;/b&gt; %2 s &amp;nbsp; &lt;b&gt;Δt&lt;/b&gt; %3 s &amp;nbsp; &lt;b&gt;1/Δt&lt;/b&gt; %4 Hz</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopePage</name>
    <message>
        <source>Add channels by address, or drag objects here from the object dictionary.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object address, e.g. 6064:0, 6078:0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object addresses INDEX:SUB (hex), separated by commas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polling period of new channels (max rate: as fast as the link allows)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acquisition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run (until Stop)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Single (one trigger)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal (re-arm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Roll (last seconds)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rising edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>falling edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>above level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>below level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inside window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>outside window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bit set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bit clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Roll window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Trigger on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Level 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pre-trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Post-trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit time and values to the data (key A)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cursors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A/B cursors: drag the lines to measure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analyse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spectrum and step response of the selected channel between the cursors (or in view)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whole recording…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Visible range…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export image…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>armed, waiting for the trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>triggered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, %2 lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no drivebench objects in the drop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1 &quot;%2&quot;: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the drop holds no object address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop recording to change the channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no device: connect one to add channels from it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is already recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n channel(s) ready; press Start to record.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type an object address such as 6064:0.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Channel colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No connected device: connect one first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No channels: add an object address or drag objects here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: choose a .png or .pdf file name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recordings (*.csv);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG image (*.png);;PDF (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to analyse: record or open a recording first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sampled passively from the PDO with COB-ID %1, bytes %2..%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, expected every %1 ms (later frames count as lost samples)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polling (SDO)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO (passive)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polling: the host reads each object by SDO at the rate above.
PDO (passive): samples the TPDOs that already carry the objects; sends nothing and changes neither the PDO configuration nor the NMT state (the node must be operational).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Map to TPDO…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Map the objects that are in no TPDO into one (changes the device&apos;s PDO configuration; asks first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO channels need a connected CANopen device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wait for the PDO configuration being read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the PDO configuration of node %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the connection changed or recording started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (use &quot;Map to TPDO…&quot; to map it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n PDO channel(s) added; press Start to record (node %1 must be operational).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Map to TPDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TPDO number of node %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the PDO configuration?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This changes the PDO configuration of node %1: TPDO%2 will carry %3, sent every %4 ms. Whatever TPDO%2 carried before is replaced (in the device&apos;s RAM; nothing is stored). A PLC or other master using TPDO%2 will see the change.

Change it?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing to map (add PDO channels first; stop recording)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing TPDO%1 of node %2…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TPDO%1 was not changed completely (it may be left disabled)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No PDO within %1 s for %2: %3 (the scope never changes the NMT state).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a PDO channel needs a CANopen connection</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopePlot</name>
    <message>
        <source>raw</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>db::widgets::odtext</name>
    <message>
        <source>%1 is %2 and cannot be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enter a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Commissioning tool for industrial drives.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start a simulated MovingCap in-process and connect to it over RefGo and over CANopen (SLCAN, node 50).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect to &lt;uri&gt; at start, e.g. refgo://192.168.2.150.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language of the window: de or en (default: the setting, else DRIVEBENCH_LANG, LC_ALL, LC_MESSAGES, LANG).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Demo drive listening at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Demo drive without CANopen: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Demo drive CANopen at %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sim</name>
    <message>
        <source>Simulated drives on 127.0.0.1.

Devices:
  movingcap   a MovingCap ETH drive (RefGo and SLCAN doors)
  canopen     CANopen nodes driven by a device description (SLCAN and/or virtualcan doors)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve RefGo on this TCP port (0 = chosen by the OS).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset an object before serving, e.g. 3511:8=110 (repeatable).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve CANopen (movingcap: node 50) as SLCAN over TCP on this port (0 = chosen by the OS).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>canopen: also serve on this Qt virtualcan interface.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>canopen: node ids, e.g. 1,2,5 (default 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>canopen: device description of the nodes (EDS, DCF, XDD, XDC, JSON; default: the built-in test node).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>canopen: this node&apos;s SDO server stays silent (repeatable).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>movingcap: writes to this object fail with a device error (failure mode for tests; repeatable).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Which device: movingcap.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
