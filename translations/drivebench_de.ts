<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>ComparisonReport</name>
    <message>
        <source>Parameter Comparison</source>
        <translation>Parametervergleich</translation>
    </message>
    <message>
        <source>Date:</source>
        <translation>Datum:</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Gerät:</translation>
    </message>
    <message>
        <source>Vendor:</source>
        <translation>Hersteller:</translation>
    </message>
    <message>
        <source>Product:</source>
        <translation>Produkt:</translation>
    </message>
    <message>
        <source>Revision:</source>
        <translation>Revision:</translation>
    </message>
    <message>
        <source>Serial number:</source>
        <translation>Seriennummer:</translation>
    </message>
    <message>
        <source>Parameter set:</source>
        <translation>Parametersatz:</translation>
    </message>
    <message>
        <source>Compared with:</source>
        <translation>Verglichen mit:</translation>
    </message>
    <message>
        <source>Result:</source>
        <translation>Ergebnis:</translation>
    </message>
    <message>
        <source>No differences</source>
        <translation>Keine Unterschiede</translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n Unterschied</numerusform>
            <numerusform>%n Unterschiede</numerusform>
        </translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Report not saved to %1: %2</source>
        <translation>Bericht nicht in %1 gespeichert: %2</translation>
    </message>
</context>
<context>
    <name>MotionChangeLog</name>
    <message>
        <source>target %1 at %2</source>
        <translation>Ziel %1 mit %2</translation>
    </message>
    <message>
        <source>distance %1 at %2</source>
        <translation>Weg %1 mit %2</translation>
    </message>
    <message>
        <source>velocity %1</source>
        <translation>Geschwindigkeit %1</translation>
    </message>
    <message>
        <source>method %1</source>
        <translation>Methode %1</translation>
    </message>
    <message>
        <source>block %1</source>
        <translation>Satz %1</translation>
    </message>
    <message>
        <source>torque %1</source>
        <translation>Moment %1</translation>
    </message>
    <message>
        <source>command removed</source>
        <translation>Befehl entfernt</translation>
    </message>
    <message>
        <source>ended by another command</source>
        <translation>von einem anderen Befehl beendet</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>ratio %1:%2</source>
        <translation>Übersetzung %1:%2</translation>
    </message>
</context>
<context>
    <name>Nm17x</name>
    <message>
        <source>%1 has %2 bytes, 8 expected</source>
        <translation>%1 hat %2 Bytes, 8 erwartet</translation>
    </message>
    <message>
        <source>%1 needs a speed (slow, medium, fast)</source>
        <translation>%1 braucht eine Geschwindigkeit (slow, medium, fast)</translation>
    </message>
    <message>
        <source>%1 takes no speed</source>
        <translation>%1 nimmt keine Geschwindigkeit an</translation>
    </message>
    <message>
        <source>the reserved combinations have no function</source>
        <translation>die reservierten Kombinationen haben keine Funktion</translation>
    </message>
    <message>
        <source>unknown command</source>
        <translation>unbekanntes Kommando</translation>
    </message>
    <message>
        <source>control word 0x%1 is not an allowed combination; the display would reject it with EMCY 8230h</source>
        <translation>Control-Wort 0x%1 ist keine zulässige Kombination; die Anzeige würde es mit EMCY 8230h ablehnen</translation>
    </message>
    <message>
        <source>no function</source>
        <translation>ohne Funktion</translation>
    </message>
    <message>
        <source>write D3</source>
        <translation>Sollwert in Positionswert D3 schreiben</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>reserviert</translation>
    </message>
    <message>
        <source>direct setpoint</source>
        <translation>Sollwert direkt</translation>
    </message>
    <message>
        <source>setpoint</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <source>setpoint with release</source>
        <translation>Sollwert mit Freigabe</translation>
    </message>
    <message>
        <source>plunge-cut setpoint</source>
        <translation>Sollwert Einsägen</translation>
    </message>
    <message>
        <source>plunge-cut setpoint with release</source>
        <translation>Sollwert Einsägen mit Freigabe</translation>
    </message>
    <message>
        <source>jog right</source>
        <translation>Tippen rechts</translation>
    </message>
    <message>
        <source>jog left</source>
        <translation>Tippen links</translation>
    </message>
    <message>
        <source>open clamp</source>
        <translation>Klemmung öffnen</translation>
    </message>
    <message>
        <source>close clamp</source>
        <translation>Klemmung schließen</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>Motorstopp</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>In Bewegung</translation>
    </message>
    <message>
        <source>Manual positioning abort</source>
        <translation>Manueller Positionierabbruch</translation>
    </message>
    <message>
        <source>Oscillation active</source>
        <translation>Oszilliermodus aktiv</translation>
    </message>
    <message>
        <source>Takten active</source>
        <translation>Takten aktiv</translation>
    </message>
    <message>
        <source>ExternPosi active</source>
        <translation>ExternPosi aktiv</translation>
    </message>
    <message>
        <source>Left key pressed</source>
        <translation>Linke Taste betätigt</translation>
    </message>
    <message>
        <source>Right key pressed</source>
        <translation>Rechte Taste betätigt</translation>
    </message>
    <message>
        <source>Speed output IN4</source>
        <translation>Motor-Geschwindigkeitsstufe IN4</translation>
    </message>
    <message>
        <source>Speed output IN3</source>
        <translation>Motor-Geschwindigkeitsstufe IN3</translation>
    </message>
    <message>
        <source>Direction output IN2 (right)</source>
        <translation>Motor-Richtungssignal IN2 (rechts)</translation>
    </message>
    <message>
        <source>Direction output IN1 (left)</source>
        <translation>Motor-Richtungssignal IN1 (links)</translation>
    </message>
    <message>
        <source>Arrows active</source>
        <translation>Pfeile aktiv</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Errorbit</translation>
    </message>
    <message>
        <source>In Position</source>
        <translation>In Position</translation>
    </message>
    <message>
        <source>end limit MAX violated</source>
        <translation>Endlage MAX verletzt</translation>
    </message>
    <message>
        <source>Move into the allowed range</source>
        <translation>In zulässigen Positionsbereich verfahren</translation>
    </message>
    <message>
        <source>end limit MIN violated</source>
        <translation>Endlage MIN verletzt</translation>
    </message>
    <message>
        <source>shaft does not turn despite the drive signal</source>
        <translation>Gerätewelle dreht sich trotz Fahrsignal nicht</translation>
    </message>
    <message>
        <source>Check motor, cable and mechanics</source>
        <translation>Funktion des Motors überprüfen; Kabel und Mechanik von Motor über Welle zur Anzeige überprüfen</translation>
    </message>
    <message>
        <source>motor fault (overcurrent)</source>
        <translation>Motor-Störung (Überstrom)</translation>
    </message>
    <message>
        <source>Fix the motor fault</source>
        <translation>Motorfehler beheben</translation>
    </message>
    <message>
        <source>target window not reached</source>
        <translation>Zielfenster nicht erreicht</translation>
    </message>
    <message>
        <source>Enlarge the tolerance window or switch to creep speed earlier</source>
        <translation>Toleranzfenster größer wählen oder Umschaltung auf Kriechgang früher setzen</translation>
    </message>
    <message>
        <source>direction error: the spindle turns the wrong way</source>
        <translation>Richtungsfehler: Spindel dreht in falsche Richtung</translation>
    </message>
    <message>
        <source>Check the motor direction setting and the motor wiring</source>
        <translation>Drehrichtung Motor und Kabelanschluss zum Motor prüfen</translation>
    </message>
    <message>
        <source>setpoint above end limit MAX (motor does not start)</source>
        <translation>Sollwert &gt; Endlage MAX (Motor fährt nicht los)</translation>
    </message>
    <message>
        <source>Send a valid setpoint (mind the loop travel)</source>
        <translation>Neuen gültigen Sollwert senden (Schleifenfahrt berücksichtigen)</translation>
    </message>
    <message>
        <source>setpoint below end limit MIN (motor does not start)</source>
        <translation>Sollwert &lt; Endlage MIN (Motor fährt nicht los)</translation>
    </message>
    <message>
        <source>collision limit violated</source>
        <translation>Endlage Kollision verletzt</translation>
    </message>
    <message>
        <source>setpoint between end limit and collision limit</source>
        <translation>Sollwert befindet sich zwischen Endlage und Kollision</translation>
    </message>
    <message>
        <source>no encoder signal: the position cannot be read</source>
        <translation>Kein Gebersignal: Position kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>Check the sensor and its cable</source>
        <translation>Sensor und Kabel prüfen</translation>
    </message>
    <message>
        <source>the encoder reports an error: the position is wrong</source>
        <translation>Geber meldet Fehler: Position ist falsch</translation>
    </message>
    <message>
        <source>Fix the sensor</source>
        <translation>Fehler des SSI-Drehgebers beheben</translation>
    </message>
    <message>
        <source>CAN communication error</source>
        <translation>CAN-Kommunikationsfehler</translation>
    </message>
    <message>
        <source>CAN buffer overflow</source>
        <translation>CAN-Pufferüberlauf</translation>
    </message>
    <message>
        <source>CAN error passive</source>
        <translation>CAN passiv</translation>
    </message>
    <message>
        <source>heartbeat error</source>
        <translation>Heartbeat-Fehler</translation>
    </message>
    <message>
        <source>recovered from bus-off</source>
        <translation>Bus-Off Recover</translation>
    </message>
    <message>
        <source>CAN-ID collision</source>
        <translation>CAN-ID-Kollision</translation>
    </message>
    <message>
        <source>RxPDO does not exist</source>
        <translation>RxPDO existiert nicht</translation>
    </message>
    <message>
        <source>object not found in the conversion table (broadcast object not allowed)</source>
        <translation>Objekt nicht gefunden in der Umsetzungstabelle (Broadcast-Objekt nicht zulässig)</translation>
    </message>
    <message>
        <source>transmit memory (FIFO) to the application controller too small</source>
        <translation>Sendespeicher (FIFO) zum Übertragen von Daten an den Applikations-Controller zu klein</translation>
    </message>
    <message>
        <source>data type not correct</source>
        <translation>Datentyp nicht korrekt</translation>
    </message>
    <message>
        <source>RxPDO2: invalid value in the control word</source>
        <translation>RxPDO2: ungültiger Wert im Register Control</translation>
    </message>
    <message>
        <source>FIFO between the internal controllers too small</source>
        <translation>FIFO-Speicher für Kommunikation zwischen den internen Controllern zu klein</translation>
    </message>
    <message>
        <source>position, status and errors could not be read several times</source>
        <translation>Daten (Position, Status, Errors) konnten mehrfach nicht gelesen werden</translation>
    </message>
    <message>
        <source>transfer to the application controller failed: no valid response</source>
        <translation>Fehler bei der Datenübertragung an den Applikations-Controller: keine gültige Rückantwort erhalten</translation>
    </message>
    <message>
        <source>faulty data read from the application controller</source>
        <translation>Fehlerhafte Daten beim Lesen vom Applikations-Controller empfangen</translation>
    </message>
    <message>
        <source>position, status and errors could not be read more than 3 times</source>
        <translation>Daten (Position, Status, Errors) konnten mehr als 3 Mal nicht gelesen werden</translation>
    </message>
    <message>
        <source>unknown state of the application state machine</source>
        <translation>Unbekannter Status der Applikations-Zustandsmaschine</translation>
    </message>
    <message>
        <source>buffer overflow when sending to the application controller</source>
        <translation>Puffer-Überlauf beim Senden an den Applikations-Controller</translation>
    </message>
    <message>
        <source>motor stop command could not be sent</source>
        <translation>Motor-Stopp-Befehl konnte nicht gesendet werden</translation>
    </message>
    <message>
        <source>addressing commands could not be sent to the application controller</source>
        <translation>Adressierungs-Kommandos konnten nicht an den Applikations-Controller gesendet werden</translation>
    </message>
    <message>
        <source>unknown state of the application state machine while writing data</source>
        <translation>Unbekannter Status der Applikations-Zustandsmaschine beim Schreiben von Daten</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Up</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Down</translation>
    </message>
    <message>
        <source>Side from which the target is approached (loop for backlash compensation)</source>
        <translation>Seite, von der die Zielposition angefahren wird (Schleifenfahrt für den Spielausgleich)</translation>
    </message>
    <message>
        <source>Up: turning the shaft right increases the actual value</source>
        <translation>Up: Drehen der Welle nach rechts erhöht den Istwert</translation>
    </message>
    <message>
        <source>Uni</source>
        <translation>Uni</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Uni-Loop</source>
        <translation>Uni-Loop</translation>
    </message>
    <message>
        <source>Off-Loop</source>
        <translation>Off-Loop</translation>
    </message>
    <message>
        <source>Direction arrows; Uni and Off position without loop</source>
        <translation>Richtungspfeile; Uni und Off positionieren ohne Schleifenfahrt</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>On: the correction 2010h is added to actual value and setpoint</source>
        <translation>Ein: die Istwertkorrektur 2010h wird zu Istwert und Sollwert addiert</translation>
    </message>
    <message>
        <source>Ever</source>
        <translation>Ever</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Key</translation>
    </message>
    <message>
        <source>Slow</source>
        <translation>Slow</translation>
    </message>
    <message>
        <source>Middle</source>
        <translation>Middle</translation>
    </message>
    <message>
        <source>Fast</source>
        <translation>Fast</translation>
    </message>
    <message>
        <source>Display only: values on the bus stay in 1/100 mm</source>
        <translation>Nur für die Anzeige: Werte auf dem Bus bleiben in 1/100 mm</translation>
    </message>
    <message>
        <source>slow</source>
        <translation>langsam</translation>
    </message>
    <message>
        <source>medium</source>
        <translation>mittel</translation>
    </message>
    <message>
        <source>fast</source>
        <translation>schnell</translation>
    </message>
    <message>
        <source>group %1</source>
        <translation>Gruppe %1</translation>
    </message>
    <message>
        <source>Standard / Oscillating</source>
        <translation>Standard / Oszillieren</translation>
    </message>
    <message>
        <source>Takten</source>
        <translation>Takten</translation>
    </message>
    <message>
        <source>ExternPosi</source>
        <translation>ExternPosi</translation>
    </message>
    <message>
        <source>Standard</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>start group %1</source>
        <translation>Startgruppe %1</translation>
    </message>
    <message>
        <source>right slow</source>
        <translation>rechts langsam</translation>
    </message>
    <message>
        <source>right medium</source>
        <translation>rechts mittel</translation>
    </message>
    <message>
        <source>right fast</source>
        <translation>rechts schnell</translation>
    </message>
    <message>
        <source>left slow</source>
        <translation>links langsam</translation>
    </message>
    <message>
        <source>left medium</source>
        <translation>links mittel</translation>
    </message>
    <message>
        <source>left fast</source>
        <translation>links schnell</translation>
    </message>
    <message>
        <source>Takes effect at the next Reset Node</source>
        <translation>Wirksam ab dem nächsten Reset Node</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a position in mm (-999.99 .. 9999.99)</source>
        <translation>„%1“ ist keine Position in mm (-999.99 .. 9999.99)</translation>
    </message>
    <message>
        <source>the CAN bus %1 is not open</source>
        <translation>der CAN-Bus %1 ist nicht geöffnet</translation>
    </message>
    <message>
        <source>node %1 is not 1..127</source>
        <translation>Knoten %1 liegt nicht in 1..127</translation>
    </message>
    <message>
        <source>setpoint %1 is outside -99999..999999 (1/100 mm)</source>
        <translation>Sollwert %1 liegt außerhalb von -99999..999999 (1/100 mm)</translation>
    </message>
    <message>
        <source>a correction of -32768 would mean &quot;keep 2010h&quot;; leave it out instead</source>
        <translation>eine Korrektur von -32768 hieße „2010h behalten“; stattdessen weglassen</translation>
    </message>
    <message>
        <source>%1 cannot be sent by broadcast; the displays would answer with EMCY 8220h</source>
        <translation>%1 kann nicht per Broadcast gesendet werden; die Anzeigen würden mit EMCY 8220h antworten</translation>
    </message>
    <message>
        <source>group %1 is not 1..8</source>
        <translation>Gruppe %1 liegt nicht in 1..8</translation>
    </message>
    <message>
        <source>preset %1 is outside -99999..999999 (1/100 mm)</source>
        <translation>Preset %1 liegt außerhalb von -99999..999999 (1/100 mm)</translation>
    </message>
    <message>
        <source>node %1, %2</source>
        <translation>Knoten %1, %2</translation>
    </message>
    <message>
        <source>node %1 is no NM170/NM172/NM174 (vendor 0x%2, product 0x%3)</source>
        <translation>Knoten %1 ist keine NM170/NM172/NM174 (Hersteller 0x%2, Produkt 0x%3)</translation>
    </message>
    <message>
        <source>node %1 has no writable object %2</source>
        <translation>Knoten %1 hat kein beschreibbares Objekt %2</translation>
    </message>
    <message>
        <source>node %1 has no object %2</source>
        <translation>Knoten %1 hat kein Objekt %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a bit rate in bit/s (e.g. 125000,250000)</source>
        <translation>„%1“ ist keine Bitrate in bit/s (z. B. 125000,250000)</translation>
    </message>
    <message>
        <source>no bit rate given (e.g. 125000,250000)</source>
        <translation>keine Bitrate angegeben (z. B. 125000,250000)</translation>
    </message>
    <message>
        <source>the bus did not open within %1 ms</source>
        <translation>der Bus wurde nicht innerhalb von %1 ms geöffnet</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Esc</source>
        <translation>Esc</translation>
    </message>
    <message>
        <source>window deactivated</source>
        <translation>Fenster deaktiviert</translation>
    </message>
    <message>
        <source>Not ready to switch on</source>
        <translation>Nicht einschaltbereit</translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation>Einschaltsperre</translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation>Einschaltbereit</translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation>Eingeschaltet</translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation>Betrieb freigegeben</translation>
    </message>
    <message>
        <source>Quick stop active</source>
        <translation>Schnellhalt aktiv</translation>
    </message>
    <message>
        <source>Fault reaction active</source>
        <translation>Fehlerreaktion aktiv</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <source>Unknown state</source>
        <translation>Unbekannter Zustand</translation>
    </message>
    <message>
        <source>No mode</source>
        <translation>Kein Modus</translation>
    </message>
    <message>
        <source>Profile position</source>
        <translation>Profilposition</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Profile velocity</source>
        <translation>Profilgeschwindigkeit</translation>
    </message>
    <message>
        <source>Profile torque</source>
        <translation>Profildrehmoment</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <source>Interpolated position</source>
        <translation>Interpolierte Position</translation>
    </message>
    <message>
        <source>Cyclic sync position</source>
        <translation>Zyklisch synchrone Position</translation>
    </message>
    <message>
        <source>Cyclic sync velocity</source>
        <translation>Zyklisch synchrone Geschwindigkeit</translation>
    </message>
    <message>
        <source>Cyclic sync torque</source>
        <translation>Zyklisch synchrones Drehmoment</translation>
    </message>
    <message>
        <source>Manufacturer mode %1</source>
        <translation>Herstellermodus %1</translation>
    </message>
    <message>
        <source>Mode %1</source>
        <translation>Modus %1</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbinde</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>closing</source>
        <translation>wird geschlossen</translation>
    </message>
    <message>
        <source>restore: %1 verified, %2 written, %3 failed, %4 mismatch, %5 skipped</source>
        <translation>restore: %1 geprüft, %2 geschrieben, %3 fehlgeschlagen, %4 abweichend, %5 übersprungen</translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>gestoppt: %1</translation>
    </message>
    <message>
        <source>stored to non-volatile memory (1010h sub 1 = &quot;save&quot;)</source>
        <translation>nichtflüchtig gespeichert (1010h Sub 1 = „save“)</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
</context>
<context>
    <name>VABus</name>
    <message>
        <source>no error</source>
        <translation>kein Fehler</translation>
    </message>
    <message>
        <source>invalid parameter value</source>
        <translation>unzulässiger Parameterwert</translation>
    </message>
    <message>
        <source>invalid data set</source>
        <translation>unzulässiger Datensatz</translation>
    </message>
    <message>
        <source>parameter not readable (write-only)</source>
        <translation>Parameter nicht lesbar (write-only)</translation>
    </message>
    <message>
        <source>parameter not writable (read-only)</source>
        <translation>Parameter nicht schreibbar (read-only)</translation>
    </message>
    <message>
        <source>EEPROM read error</source>
        <translation>Lesefehler EEPROM</translation>
    </message>
    <message>
        <source>EEPROM write error</source>
        <translation>Schreibfehler EEPROM</translation>
    </message>
    <message>
        <source>EEPROM checksum error</source>
        <translation>Prüfsummenfehler EEPROM</translation>
    </message>
    <message>
        <source>parameter not writable while the drive is running</source>
        <translation>Parameter nicht während laufenden Antriebs schreibbar</translation>
    </message>
    <message>
        <source>values of the data sets differ</source>
        <translation>Werte der Datensätze unterscheiden sich</translation>
    </message>
    <message>
        <source>not available</source>
        <translation>nicht verfügbar</translation>
    </message>
    <message>
        <source>unknown parameter</source>
        <translation>unbekannter Parameter</translation>
    </message>
    <message>
        <source>syntax error in received telegram</source>
        <translation>Syntaxfehler im empfangenen Telegramm</translation>
    </message>
    <message>
        <source>data type of the parameter does not match the number of bytes in the telegram</source>
        <translation>Datentyp des Parameters passt nicht zur Anzahl Bytes im Telegramm</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>unbekannter Fehler</translation>
    </message>
    <message>
        <source>selected system bus node not available</source>
        <translation>gewählter Systembus-Knoten nicht verfügbar</translation>
    </message>
    <message>
        <source>error code %1 (not in the VABus error table)</source>
        <translation>Fehlercode %1 (nicht in der VABus-Fehlertabelle)</translation>
    </message>
</context>
<context>
    <name>cli</name>
    <message>
        <source>drivebench command line: read and write drive objects from scripts.

Commands:</source>
        <translation>drivebench-Kommandozeile: Antriebsobjekte aus Skripten lesen und schreiben.

Befehle:</translation>
    </message>
    <message>
        <source>

Exit codes: 0 ok, 1 failure, 2 usage, 3 connection, 4 timeout, 5 malformed answer, 6 device error, 128 + N stopped by signal N (record: 130 Ctrl-C, 143 SIGTERM).</source>
        <translation>

Exit-Codes: 0 ok, 1 Fehler, 2 Aufruf, 3 Verbindung, 4 Zeitüberschreitung, 5 fehlerhafte Antwort, 6 Gerätefehler, 128 + N durch Signal N gestoppt (record: 130 Strg-C, 143 SIGTERM).</translation>
    </message>
    <message>
        <source>Time limit per request in ms (default 1000).</source>
        <translation>Zeitlimit je Anfrage in ms (Standard 1000).</translation>
    </message>
    <message>
        <source>Time limit for connecting in ms (default 3000).</source>
        <translation>Zeitlimit für den Verbindungsaufbau in ms (Standard 3000).</translation>
    </message>
    <message>
        <source>Print integers in hex.</source>
        <translation>Ganzzahlen hexadezimal ausgeben.</translation>
    </message>
    <message>
        <source>Data type of an object the device description does not know (u8, i16, u32, REAL32, ...).</source>
        <translation>Datentyp eines Objekts, das die Gerätebeschreibung nicht kennt (u8, i16, u32, REAL32, ...).</translation>
    </message>
    <message>
        <source>Name what is printed and log the traffic on stderr.</source>
        <translation>Ausgaben benennen und den Datenverkehr auf stderr protokollieren.</translation>
    </message>
    <message>
        <source>read/write: the value as raw bytes to/from this file.</source>
        <translation>read/write: der Wert als Rohbytes aus/in diese Datei.</translation>
    </message>
    <message>
        <source>dcf: the file to write.</source>
        <translation>dcf: die zu schreibende Datei.</translation>
    </message>
    <message>
        <source>CANopen SDO mode: auto (default), expedited, segmented, block.</source>
        <translation>CANopen-SDO-Modus: auto (Standard), expedited, segmented, block.</translation>
    </message>
    <message>
        <source>nmt: every node (broadcast).</source>
        <translation>nmt: alle Knoten (Broadcast).</translation>
    </message>
    <message>
        <source>Language of the messages: de or en (default: DRIVEBENCH_LANG, else LC_ALL, LC_MESSAGES, LANG).</source>
        <translation>Sprache der Meldungen: de oder en (Standard: DRIVEBENCH_LANG, sonst LC_ALL, LC_MESSAGES, LANG).</translation>
    </message>
    <message>
        <source>What to do (see above).</source>
        <translation>Was zu tun ist (siehe oben).</translation>
    </message>
    <message>
        <source>drivebench-cli: --lang takes one of: %1</source>
        <translation>drivebench-cli: --lang erwartet eines von: %1</translation>
    </message>
    <message>
        <source>--sdo needs a canopen+... URI</source>
        <translation>--sdo braucht eine canopen+...-URI</translation>
    </message>
    <message>
        <source> (default port %1)</source>
        <translation> (Standardport %1)</translation>
    </message>
    <message>
        <source>unknown type &apos;%1&apos; (e.g. u16, i32, UNSIGNED8, REAL32)</source>
        <translation>unbekannter Typ „%1“ (z. B. u16, i32, UNSIGNED8, REAL32)</translation>
    </message>
    <message>
        <source>(not in the description)</source>
        <translation>(nicht in der Beschreibung)</translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation>Lesen von %1</translation>
    </message>
    <message>
        <source>(unknown object)</source>
        <translation>(unbekanntes Objekt)</translation>
    </message>
    <message>
        <source>write takes either VALUE or --file FILE</source>
        <translation>write erwartet entweder WERT oder --file DATEI</translation>
    </message>
    <message>
        <source>&apos;refgo&apos; needs a refgo:// URI, not %1</source>
        <translation>„refgo“ braucht eine refgo://-URI, nicht %1</translation>
    </message>
    <message>
        <source>list the protocols and their URI forms</source>
        <translation>die Protokolle und ihre URI-Formen auflisten</translation>
    </message>
    <message>
        <source>write one object, e.g. write refgo://HOST 6083:0 2000</source>
        <translation>ein Objekt schreiben, z. B. write refgo://HOST 6083:0 2000</translation>
    </message>
    <message>
        <source>send one RefGo command and print its result lines, e.g. TP</source>
        <translation>einen RefGo-Befehl senden und seine Ergebniszeilen ausgeben, z. B. TP</translation>
    </message>
    <message>
        <source>list the CANopen nodes on the bus of URI (no ?node= needed)</source>
        <translation>die CANopen-Knoten am Bus der URI auflisten (kein ?node= nötig)</translation>
    </message>
    <message>
        <source>NMT command to the URI&apos;s node, or to every node with --all</source>
        <translation>NMT-Befehl an den Knoten der URI oder mit --all an alle Knoten</translation>
    </message>
    <message>
        <source>CiA 305 layer setting services</source>
        <translation>CiA 305 Layer Setting Services (LSS)</translation>
    </message>
    <message>
        <source>print the node&apos;s PDO configuration</source>
        <translation>die PDO-Konfiguration des Knotens ausgeben</translation>
    </message>
    <message>
        <source>write a DCF of the device&apos;s current values (?eds= needed)</source>
        <translation>eine DCF mit den aktuellen Werten des Geräts schreiben (?eds= nötig)</translation>
    </message>
    <message>
        <source>check an EDS/DCF/XDD/XDC file: summary and warnings</source>
        <translation>eine EDS/DCF/XDD/XDC-Datei prüfen: Zusammenfassung und Warnungen</translation>
    </message>
    <message>
        <source>save every storable object of the device to a parameter set</source>
        <translation>jedes speicherbare Objekt des Geräts in einen Parametersatz sichern</translation>
    </message>
    <message>
        <source>write a parameter set (or its selected rows) safely, verify, optionally store</source>
        <translation>einen Parametersatz (oder ausgewählte Zeilen) sicher schreiben, prüfen, optional speichern</translation>
    </message>
    <message>
        <source>compare two parameter sets, each a URI or a file; exit 1 if they differ</source>
        <translation>zwei Parametersätze vergleichen, je eine URI oder Datei; Exit-Code 1, wenn sie sich unterscheiden</translation>
    </message>
    <message>
        <source>print every readable object with its value</source>
        <translation>jedes lesbare Objekt mit seinem Wert ausgeben</translation>
    </message>
    <message>
        <source>decode the LED Morse IP from a video or a CSV of samples</source>
        <translation>die per LED gemorste IP aus einem Video oder einer CSV mit Messwerten dekodieren</translation>
    </message>
    <message>
        <source>enable the drive (MC_Power on); prints the axis state</source>
        <translation>den Antrieb freigeben (MC_Power ein); gibt den Achszustand aus</translation>
    </message>
    <message>
        <source>disable the drive (MC_Power off)</source>
        <translation>den Antrieb sperren (MC_Power aus)</translation>
    </message>
    <message>
        <source>fault reset (MC_Reset)</source>
        <translation>Störung quittieren (MC_Reset)</translation>
    </message>
    <message>
        <source>move and wait for Done; prints the final actual position</source>
        <translation>fahren und auf Done warten; gibt die erreichte Istposition aus</translation>
    </message>
    <message>
        <source>jog at V for MS ms, then halt; prints the position</source>
        <translation>mit V für MS ms tippen, dann anhalten; gibt die Position aus</translation>
    </message>
    <message>
        <source>record objects (host polling or CANopen PDOs) to CSV, optionally triggered</source>
        <translation>Objekte als CSV aufzeichnen (Abfrage durch den Rechner oder CANopen-PDOs), optional getriggert</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>no CANopen node answered on %1 within %2 ms</source>
        <translation>kein CANopen-Knoten hat auf %1 innerhalb von %2 ms geantwortet</translation>
    </message>
    <message>
        <source>unknown NMT command &apos;%1&apos; (start, stop, preop, reset, reset-comm)</source>
        <translation>unbekannter NMT-Befehl „%1“ (start, stop, preop, reset, reset-comm)</translation>
    </message>
    <message>
        <source>nmt (or give --all)</source>
        <translation>nmt (oder --all angeben)</translation>
    </message>
    <message>
        <source>cannot send NMT</source>
        <translation>NMT kann nicht gesendet werden</translation>
    </message>
    <message>
        <source>unknown LSS action &apos;%1&apos; (%2)</source>
        <translation>unbekannte LSS-Aktion „%1“ (%2)</translation>
    </message>
    <message>
        <source>switch-selective takes VENDOR,PRODUCT,REVISION,SERIAL (e.g. 0xEC,0x71,0x10001,0x4D52F567)</source>
        <translation>switch-selective erwartet HERSTELLER,PRODUKT,REVISION,SERIENNUMMER (z. B. 0xEC,0x71,0x10001,0x4D52F567)</translation>
    </message>
    <message>
        <source>set-node takes a node id 1..127</source>
        <translation>set-node erwartet eine Knoten-ID 1..127</translation>
    </message>
    <message>
        <source>set-bitrate takes a CiA bit rate: 1000k, 800k, 500k, 250k, 125k, 100k, 50k, 20k or 10k</source>
        <translation>set-bitrate erwartet eine CiA-Bitrate: 1000k, 800k, 500k, 250k, 125k, 100k, 50k, 20k oder 10k</translation>
    </message>
    <message>
        <source>LSS %1</source>
        <translation>LSS %1</translation>
    </message>
    <message>
        <source>set-node %1</source>
        <translation>set-node %1</translation>
    </message>
    <message>
        <source>set-bitrate %1</source>
        <translation>set-bitrate %1</translation>
    </message>
    <message>
        <source>LSS fastscan</source>
        <translation>LSS-Fastscan</translation>
    </message>
    <message>
        <source>LSS inquire (is a slave in configuration mode? use switch-selective or switch-global first)</source>
        <translation>LSS-Abfrage (ist ein Slave im Konfigurationsmodus? zuerst switch-selective oder switch-global verwenden)</translation>
    </message>
    <message>
        <source>pdo needs a canopen+... URI</source>
        <translation>pdo braucht eine canopen+...-URI</translation>
    </message>
    <message>
        <source>reading the PDO configuration</source>
        <translation>Lesen der PDO-Konfiguration</translation>
    </message>
    <message>
        <source>dcf needs the output file: -o FILE</source>
        <translation>dcf braucht die Ausgabedatei: -o DATEI</translation>
    </message>
    <message>
        <source>no device description for %1: give ?eds=FILE</source>
        <translation>keine Gerätebeschreibung für %1: ?eds=DATEI angeben</translation>
    </message>
    <message>
        <source>, %1 objects not readable</source>
        <translation>, %1 Objekte nicht lesbar</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source> (resolved for node %1)</source>
        <translation> (aufgelöst für Knoten %1)</translation>
    </message>
    <message>
        <source> (symbolic, no node id)</source>
        <translation> (symbolisch, keine Knoten-ID)</translation>
    </message>
    <message>
        <source>--%1 takes a number, not &apos;%2&apos;</source>
        <translation>--%1 erwartet eine Zahl, nicht „%2“</translation>
    </message>
    <message>
        <source>--wait takes ms &gt; 0</source>
        <translation>--wait erwartet ms &gt; 0</translation>
    </message>
    <message>
        <source>reading the scaling</source>
        <translation>Lesen der Skalierung</translation>
    </message>
    <message>
        <source>no status from the drive</source>
        <translation>kein Status vom Antrieb</translation>
    </message>
    <message>
        <source>%1 not done within %2 ms (--wait); axis stopped</source>
        <translation>%1 nicht innerhalb von %2 ms abgeschlossen (--wait); Achse gestoppt</translation>
    </message>
    <message>
        <source>move: absolute target (user units).</source>
        <translation>move: absolutes Ziel (Anwendereinheiten).</translation>
    </message>
    <message>
        <source>move: distance from the actual position.</source>
        <translation>move: Weg ab der Istposition.</translation>
    </message>
    <message>
        <source>move: distance from the last target (MC_MoveAdditive).</source>
        <translation>move: Weg ab dem letzten Ziel (MC_MoveAdditive).</translation>
    </message>
    <message>
        <source>motion commands: longest wait for the end (ms, default 60000).</source>
        <translation>Bewegungsbefehle: längste Wartezeit auf das Ende (ms, Standard 60000).</translation>
    </message>
    <message>
        <source>move takes exactly one of --abs, --rel, --add</source>
        <translation>move erwartet genau eines von --abs, --rel, --add</translation>
    </message>
    <message>
        <source>--time takes 1..%1 ms</source>
        <translation>--time erwartet 1..%1 ms</translation>
    </message>
    <message>
        <source>MC_Halt not done within %1 ms (--wait); axis stopped</source>
        <translation>MC_Halt nicht innerhalb von %1 ms abgeschlossen (--wait); Achse gestoppt</translation>
    </message>
    <message>
        <source>partial backup: %1 of %2 objects could not be read; not a complete set</source>
        <translation>Teilsicherung: %1 von %2 Objekten konnten nicht gelesen werden; kein vollständiger Satz</translation>
    </message>
    <message>
        <source>%1 is a set for &apos;%2&apos;, but %3 is a &apos;%4&apos;</source>
        <translation>%1 ist ein Parametersatz für „%2“, aber %3 ist ein „%4“</translation>
    </message>
    <message>
        <source>%1 does not record the product code (1018h.2 could not be read when it was made), so it cannot be checked against the device; give --ignore-identity to restore it anyway</source>
        <translation>%1 enthält keinen Produktcode (1018h.2 war beim Erstellen nicht lesbar) und kann daher nicht mit dem Gerät abgeglichen werden; mit --ignore-identity trotzdem wiederherstellen</translation>
    </message>
    <message>
        <source>cannot check the device&apos;s product code (1018h.2); --ignore-identity restores without the check</source>
        <translation>der Produktcode des Geräts (1018h.2) kann nicht geprüft werden; --ignore-identity stellt ohne die Prüfung wieder her</translation>
    </message>
    <message>
        <source>%1 is a set for product code 0x%2, but the device reports 0x%3</source>
        <translation>%1 ist ein Parametersatz für Produktcode 0x%2, das Gerät meldet aber 0x%3</translation>
    </message>
    <message>
        <source>restore: store to non-volatile memory afterwards (1010h sub 1 = &quot;save&quot;) when every row verified.</source>
        <translation>restore: anschließend nichtflüchtig speichern (1010h Sub 1 = „save“), wenn jede Zeile geprüft ist.</translation>
    </message>
    <message>
        <source>restore: do not read each object back.</source>
        <translation>restore: die Objekte nicht zurücklesen.</translation>
    </message>
    <message>
        <source>restore: skip the product check (a set from another product, or one whose product code is unknown).</source>
        <translation>restore: Produktprüfung überspringen (ein Satz eines anderen Produkts oder mit unbekanntem Produktcode).</translation>
    </message>
    <message>
        <source>backup needs the output file: -o FILE</source>
        <translation>backup braucht die Ausgabedatei: -o DATEI</translation>
    </message>
    <message>
        <source>nothing was written</source>
        <translation>nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>the %1 objects read and the failures are in %2</source>
        <translation>die %1 gelesenen Objekte und die Fehler stehen in %2</translation>
    </message>
    <message>
        <source>backup incomplete, %1 not written (%2)</source>
        <translation>Sicherung unvollständig, %1 nicht geschrieben (%2)</translation>
    </message>
    <message>
        <source>%1 holds no object: nothing to restore</source>
        <translation>%1 enthält kein Objekt: nichts wiederherzustellen</translation>
    </message>
    <message>
        <source>--only: %1 is not in %2</source>
        <translation>--only: %1 ist nicht in %2</translation>
    </message>
    <message>
        <source>--%1 takes a number of seconds &gt;= 0, not &apos;%2&apos;</source>
        <translation>--%1 erwartet eine Anzahl Sekunden &gt;= 0, nicht „%2“</translation>
    </message>
    <message>
        <source>--%1 takes %2 (%3..%4), not &apos;%5&apos;</source>
        <translation>--%1 erwartet %2 (%3..%4), nicht „%5“</translation>
    </message>
    <message>
        <source>--obj %1 given twice</source>
        <translation>--obj %1 doppelt angegeben</translation>
    </message>
    <message>
        <source>record needs -o FILE.csv</source>
        <translation>record braucht -o DATEI.csv</translation>
    </message>
    <message>
        <source>--rate-ms takes a number of ms &gt;= 0 (0 = as fast as the link allows)</source>
        <translation>--rate-ms erwartet eine Anzahl ms &gt;= 0 (0 = so schnell die Verbindung erlaubt)</translation>
    </message>
    <message>
        <source>--capacity takes a number of samples &gt;= 1</source>
        <translation>--capacity erwartet eine Anzahl Messwerte &gt;= 1</translation>
    </message>
    <message>
        <source>a TPDO number</source>
        <translation>eine TPDO-Nummer</translation>
    </message>
    <message>
        <source>--event-ms goes with --configure-tpdo N</source>
        <translation>--event-ms gehört zu --configure-tpdo N</translation>
    </message>
    <message>
        <source>the event timer in ms</source>
        <translation>der Event-Timer in ms</translation>
    </message>
    <message>
        <source>record needs --duration S (&gt; 0) or --trigger SPEC</source>
        <translation>record braucht --duration S (&gt; 0) oder --trigger SPEC</translation>
    </message>
    <message>
        <source>record: sample period per object in ms (default 10; 0 = as fast as the link allows).</source>
        <translation>record: Abtastperiode je Objekt in ms (Standard 10; 0 = so schnell die Verbindung erlaubt).</translation>
    </message>
    <message>
        <source>record: seconds to record (with --trigger: the default --post).</source>
        <translation>record: Aufzeichnungsdauer in Sekunden (mit --trigger: der Standard für --post).</translation>
    </message>
    <message>
        <source>record: CHANNEL,CONDITION, e.g. 6064:0,rising,100 or 6041:0,bit3,set.</source>
        <translation>record: KANAL,BEDINGUNG, z. B. 6064:0,rising,100 oder 6041:0,bit3,set.</translation>
    </message>
    <message>
        <source>record: seconds kept before the trigger.</source>
        <translation>record: Sekunden vor dem Trigger, die behalten werden.</translation>
    </message>
    <message>
        <source>record: seconds recorded after the trigger.</source>
        <translation>record: Sekunden, die nach dem Trigger aufgezeichnet werden.</translation>
    </message>
    <message>
        <source>record: longest wait for the trigger in s (default 30).</source>
        <translation>record: längste Wartezeit auf den Trigger in s (Standard 30).</translation>
    </message>
    <message>
        <source>record: most samples kept per object (default 10000000).</source>
        <translation>record: höchstens so viele Messwerte je Objekt behalten (Standard 10000000).</translation>
    </message>
    <message>
        <source>record: CANopen: sample the objects passively from the TPDOs that carry them (writes nothing).</source>
        <translation>record: CANopen: die Objekte passiv aus den TPDOs abtasten, die sie übertragen (schreibt nichts).</translation>
    </message>
    <message>
        <source>record: CANopen: first map the objects into TPDO N (CHANGES the device&apos;s PDO configuration), then sample it.</source>
        <translation>record: CANopen: zuerst die Objekte in TPDO N mappen (ÄNDERT die PDO-Konfiguration des Geräts), dann abtasten.</translation>
    </message>
    <message>
        <source>record: event timer of --configure-tpdo in ms (default --rate-ms, else 10).</source>
        <translation>record: Event-Timer von --configure-tpdo in ms (Standard --rate-ms, sonst 10).</translation>
    </message>
    <message>
        <source>TPDO%1 (COB-ID 0x%2)</source>
        <translation>TPDO%1 (COB-ID 0x%2)</translation>
    </message>
    <message>
        <source>--pdo and --configure-tpdo need a canopen+... URI</source>
        <translation>--pdo und --configure-tpdo brauchen eine canopen+...-URI</translation>
    </message>
    <message>
        <source>configuring TPDO%1 of node %2%3</source>
        <translation>konfiguriere TPDO%1 von Knoten %2%3</translation>
    </message>
    <message>
        <source> (it may be left disabled)</source>
        <translation> (er kann deaktiviert geblieben sein)</translation>
    </message>
    <message>
        <source>; use --configure-tpdo N to map it (this changes the device&apos;s PDO configuration)</source>
        <translation>; mit --configure-tpdo N mappen (das ändert die PDO-Konfiguration des Geräts)</translation>
    </message>
    <message>
        <source>no PDO arrived from node %1 within %2 s (%3): %4</source>
        <translation>kein PDO von Knoten %1 innerhalb von %2 s (%3): %4</translation>
    </message>
    <message>
        <source> (drivebench-cli nmt %1 start; record never changes the NMT state)</source>
        <translation> (drivebench-cli nmt %1 start; record ändert den NMT-Zustand nie)</translation>
    </message>
    <message>
        <source> (--configure-tpdo N --event-ms MS makes it cyclic)</source>
        <translation> (--configure-tpdo N --event-ms MS macht ihn zyklisch)</translation>
    </message>
    <message>
        <source>interrupted by %1</source>
        <translation>unterbrochen durch %1</translation>
    </message>
    <message>
        <source>all %1 reads failed, the last: %2</source>
        <translation>alle %1 Lesevorgänge fehlgeschlagen, zuletzt: %2</translation>
    </message>
    <message>
        <source>the read of %1 got no answer in %2 s</source>
        <translation>das Lesen von %1 bekam in %2 s keine Antwort</translation>
    </message>
    <message>
        <source>no sample arrived</source>
        <translation>kein Messwert eingetroffen</translation>
    </message>
    <message>
        <source>trigger %1 did not fire within %2 s; nothing written</source>
        <translation>Trigger %1 hat nicht innerhalb von %2 s ausgelöst; nichts geschrieben</translation>
    </message>
    <message>
        <source>no sample recorded in %1 s, nothing written: %2</source>
        <translation>in %1 s kein Messwert aufgezeichnet, nichts geschrieben: %2</translation>
    </message>
    <message>
        <source>recording stopped early (%1 written)</source>
        <translation>Aufzeichnung vorzeitig beendet (%1 geschrieben)</translation>
    </message>
    <message>
        <source>%1 of %2 reads failed (%3 samples lost in all, gaps are marked in %4), the last: %5</source>
        <translation>%1 von %2 Lesevorgängen fehlgeschlagen (insgesamt %3 Messwerte verloren, Lücken sind in %4 markiert), zuletzt: %5</translation>
    </message>
    <message>
        <source>drivebench-cli: no command given; try drivebench-cli --help</source>
        <translation>drivebench-cli: kein Befehl angegeben; siehe drivebench-cli --help</translation>
    </message>
    <message>
        <source>drivebench-cli: unknown command &apos;%1&apos;; try drivebench-cli --help</source>
        <translation>drivebench-cli: unbekannter Befehl „%1“; siehe drivebench-cli --help</translation>
    </message>
    <message>
        <source>drivebench-cli: usage: drivebench-cli %1 %2</source>
        <translation>drivebench-cli: Aufruf: drivebench-cli %1 %2</translation>
    </message>
    <message>
        <source>drivebench-cli: --timeout and --connect-timeout take a positive number of ms</source>
        <translation>drivebench-cli: --timeout und --connect-timeout erwarten eine positive Anzahl ms</translation>
    </message>
    <message>
        <source>warning: %1: %2</source>
        <translation>Warnung: %1: %2</translation>
    </message>
    <message>
        <source>drivebench-cli: region must be X,Y,W,H in frame pixels, got &quot;%1&quot;</source>
        <translation>drivebench-cli: der Bereich muss X,Y,B,H in Bildpixeln sein, erhalten „%1“</translation>
    </message>
    <message>
        <source>drivebench-cli: %1: no LED found: no region of the video blinks (give the region as X,Y,W,H)</source>
        <translation>drivebench-cli: %1: keine LED gefunden: kein Bereich des Videos blinkt (den Bereich als X,Y,B,H angeben)</translation>
    </message>
    <message>
        <source>drivebench-cli: warning: %1</source>
        <translation>drivebench-cli: Warnung: %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>skipped: %1</source>
        <translation>übersprungen: %1</translation>
    </message>
    <message>
        <source>warning: --ignore-identity: the set&apos;s product is not checked against the device</source>
        <translation>Warnung: --ignore-identity: das Produkt des Satzes wird nicht mit dem Gerät abgeglichen</translation>
    </message>
    <message>
        <source>recording: samples arriving -&gt; %1 (Ctrl-C stops and writes what was recorded)</source>
        <translation>Aufzeichnung: Messwerte treffen ein -&gt; %1 (Strg-C stoppt und schreibt das Aufgezeichnete)</translation>
    </message>
    <message>
        <source>drivebench-cli: the PDO configuration of node %1 was changed (RAM only, not stored): %2</source>
        <translation>drivebench-cli: die PDO-Konfiguration von Knoten %1 wurde geändert (nur RAM, nicht gespeichert): %2</translation>
    </message>
    <message>
        <source>drivebench-cli: %1 samples were lost (%2); gaps are marked in %3</source>
        <translation>drivebench-cli: %1 Messwerte gingen verloren (%2); Lücken sind in %3 markiert</translation>
    </message>
    <message>
        <source>the link is slower than --rate-ms asks</source>
        <translation>die Verbindung ist langsamer, als --rate-ms verlangt</translation>
    </message>
    <message>
        <source>PDOs missed their expected period</source>
        <translation>PDOs haben ihre erwartete Periode verpasst</translation>
    </message>
    <message>
        <source>, addresses like %1</source>
        <translation>, Adressen wie %1</translation>
    </message>
    <message>
        <source>read one object, e.g. read refgo://192.168.2.150 6041:0 (ADDRESS as the protocol writes it: list-protocols shows an example)</source>
        <translation>ein Objekt lesen, z. B. read refgo://192.168.2.150 6041:0 (ADRESSE so, wie das Protokoll sie schreibt: list-protocols zeigt ein Beispiel)</translation>
    </message>
    <message>
        <source>Baumer NM170/NM172/NM174 displays on the bus of URI (S: slow, medium, fast)</source>
        <translation>Baumer-NM170/NM172/NM174-Anzeigen am Bus der URI (S: slow, medium, fast)</translation>
    </message>
    <message>
        <source>restore: only these objects, as the protocol writes addresses, e.g. 6083:0,6084:0.</source>
        <translation>restore: nur diese Objekte, Adressen wie im Protokoll, z. B. 6083:0,6084:0.</translation>
    </message>
    <message>
        <source>--only needs addresses like %1,...</source>
        <translation>--only braucht Adressen wie %1,...</translation>
    </message>
    <message>
        <source>record needs at least one --obj ADDRESS (e.g. --obj %1)</source>
        <translation>record braucht mindestens ein --obj ADRESSE (z. B. --obj %1)</translation>
    </message>
    <message>
        <source>record: an object to record, as the protocol writes addresses (repeatable).</source>
        <translation>record: ein aufzuzeichnendes Objekt, Adresse wie im Protokoll (wiederholbar).</translation>
    </message>
    <message>
        <source>VABus: write the RAM copy of the data set (data set + 5), sparing the inverter&apos;s EEPROM; lost at power-off.</source>
        <translation>VABus: die RAM-Kopie des Datensatzes schreiben (Datensatz + 5), schont das EEPROM des Umrichters; geht beim Ausschalten verloren.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a node id 1..127</source>
        <translation>„%1“ ist keine Knoten-ID 1..127</translation>
    </message>
    <message>
        <source>--%1 takes a number %2..%3</source>
        <translation>--%1 erwartet eine Zahl %2..%3</translation>
    </message>
    <message>
        <source>no NM170/NM172/NM174 display answered on %1</source>
        <translation>keine NM170/NM172/NM174-Anzeige hat auf %1 geantwortet</translation>
    </message>
    <message>
        <source>node %1: %2</source>
        <translation>Knoten %1: %2</translation>
    </message>
    <message>
        <source>node %1 did not report In Position within %2 s</source>
        <translation>Knoten %1 hat nicht innerhalb von %2 s In Position gemeldet</translation>
    </message>
    <message>
        <source>usage: nm17x URI setpoint NODE MM [--release] [--direct] [--plunge SPEED] [--correction MM]</source>
        <translation>Aufruf: nm17x URI setpoint KNOTEN MM [--release] [--direct] [--plunge TEMPO] [--correction MM]</translation>
    </message>
    <message>
        <source>--plunge takes slow, medium or fast, and not with --direct</source>
        <translation>--plunge erwartet slow, medium oder fast, und nicht zusammen mit --direct</translation>
    </message>
    <message>
        <source>node %1, 2010:0</source>
        <translation>Knoten %1, 2010:0</translation>
    </message>
    <message>
        <source>node %1: setpoint %2 set (no release)</source>
        <translation>Knoten %1: Sollwert %2 gesetzt (ohne Freigabe)</translation>
    </message>
    <message>
        <source>usage: nm17x URI jog NODE left|right --speed slow|medium|fast</source>
        <translation>Aufruf: nm17x URI jog KNOTEN left|right --speed slow|medium|fast</translation>
    </message>
    <message>
        <source>jog needs --speed slow, medium or fast</source>
        <translation>jog braucht --speed slow, medium oder fast</translation>
    </message>
    <message>
        <source>node %1: jogging %2 at %3 speed until stop or limit</source>
        <translation>Knoten %1: tippt %2 mit Tempo %3 bis Stopp oder Grenze</translation>
    </message>
    <message>
        <source>usage: nm17x URI stop NODE|all</source>
        <translation>Aufruf: nm17x URI stop KNOTEN|all</translation>
    </message>
    <message>
        <source>stop sent to %1</source>
        <translation>Stopp an %1 gesendet</translation>
    </message>
    <message>
        <source>usage: nm17x URI broadcast unit mm|inch | show-id [off] | preset MM | start GROUP | stop</source>
        <translation>Aufruf: nm17x URI broadcast unit mm|inch | show-id [off] | preset MM | start GRUPPE | stop</translation>
    </message>
    <message>
        <source>start takes a group 1..8</source>
        <translation>start erwartet eine Gruppe 1..8</translation>
    </message>
    <message>
        <source>broadcast %1 %2 sent on 201h</source>
        <translation>Broadcast %1 %2 auf 201h gesendet</translation>
    </message>
    <message>
        <source>usage: nm17x URI control NODE WORD [--setpoint MM] [--correction MM]</source>
        <translation>Aufruf: nm17x URI control KNOTEN WORT [--setpoint MM] [--correction MM]</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a 16-bit control word</source>
        <translation>„%1“ ist kein 16-Bit-Steuerwort</translation>
    </message>
    <message>
        <source>--correction takes -327.67..327.67 mm</source>
        <translation>--correction erwartet -327.67..327.67 mm</translation>
    </message>
    <message>
        <source>node %1: %2 sent</source>
        <translation>Knoten %1: %2 gesendet</translation>
    </message>
    <message>
        <source>node %1 TxPDO1 position %2 status %3 errors %4</source>
        <translation>Knoten %1 TxPDO1 Position %2 Status %3 Fehler %4</translation>
    </message>
    <message>
        <source>node %1 TxPDO2 position %2 correction %3 status %4</source>
        <translation>Knoten %1 TxPDO2 Position %2 Korrektur %3 Status %4</translation>
    </message>
    <message>
        <source>node %1 EMCY %2h sub %3: %4</source>
        <translation>Knoten %1 EMCY %2h Sub %3: %4</translation>
    </message>
    <message>
        <source>watching %1 for %2 s</source>
        <translation>beobachte %1 für %2 s</translation>
    </message>
    <message>
        <source>address needs --broadcast FIRST (the first node id)</source>
        <translation>address braucht --broadcast ERSTE (die erste Knoten-ID)</translation>
    </message>
    <message>
        <source>offering node %1: turn the shaft (or press a key) of the display that should become node %1</source>
        <translation>biete Knoten %1 an: die Welle der Anzeige drehen (oder eine Taste drücken), die Knoten %1 werden soll</translation>
    </message>
    <message>
        <source>node %1 assigned</source>
        <translation>Knoten %1 zugewiesen</translation>
    </message>
    <message>
        <source>assigned node ids: %1; every node reset</source>
        <translation>zugewiesene Knoten-IDs: %1; jeder Knoten zurückgesetzt</translation>
    </message>
    <message>
        <source>nm17x setpoint: start the motor at once.</source>
        <translation>nm17x setpoint: den Motor sofort starten.</translation>
    </message>
    <message>
        <source>nm17x setpoint: with release, without loop.</source>
        <translation>nm17x setpoint: mit Freigabe, ohne Schleifenfahrt.</translation>
    </message>
    <message>
        <source>nm17x setpoint: plunge cut at this speed.</source>
        <translation>nm17x setpoint: Einsägen mit dieser Geschwindigkeit.</translation>
    </message>
    <message>
        <source>nm17x: actual value correction in mm.</source>
        <translation>nm17x: Istwertkorrektur in mm.</translation>
    </message>
    <message>
        <source>nm17x control: the setpoint in mm.</source>
        <translation>nm17x control: der Sollwert in mm.</translation>
    </message>
    <message>
        <source>nm17x jog: slow, medium or fast.</source>
        <translation>nm17x jog: slow, medium oder fast.</translation>
    </message>
    <message>
        <source>nm17x address: first node id of the line.</source>
        <translation>nm17x address: erste Knoten-ID der Linie.</translation>
    </message>
    <message>
        <source>nm17x address: number of displays (default: until a step times out).</source>
        <translation>nm17x address: Anzahl Anzeigen (Standard: bis ein Schritt in eine Zeitüberschreitung läuft).</translation>
    </message>
    <message>
        <source>nm17x address: seconds the operator has per display (default 60).</source>
        <translation>nm17x address: Sekunden, die der Bediener je Anzeige hat (Standard 60).</translation>
    </message>
    <message>
        <source>nm17x setpoint: seconds to wait for In Position (default 30).</source>
        <translation>nm17x setpoint: Sekunden Wartezeit auf In Position (Standard 30).</translation>
    </message>
    <message>
        <source>nm17x watch: how long to watch (default 5).</source>
        <translation>nm17x watch: wie lange beobachtet wird (Standard 5).</translation>
    </message>
    <message>
        <source>unknown nm17x command &apos;%1&apos; (%2)</source>
        <translation>unbekannter nm17x-Befehl „%1“ (%2)</translation>
    </message>
    <message>
        <source>run the drive&apos;s velocity mode at V for MS ms, then halt; prints the position</source>
        <translation>die Geschwindigkeitsbetriebsart des Antriebs mit V für MS ms fahren, dann anhalten; gibt die Position aus</translation>
    </message>
    <message>
        <source>brake to standstill (MC_Halt); prints the position</source>
        <translation>bis zum Stillstand bremsen (MC_Halt); gibt die Position aus</translation>
    </message>
    <message>
        <source>stop (MC_Stop: nothing else starts until standstill); prints the position</source>
        <translation>stoppen (MC_Stop: bis zum Stillstand startet nichts anderes); gibt die Position aus</translation>
    </message>
    <message>
        <source>move, jog, velocity, home: velocity (units/s).</source>
        <translation>move, jog, velocity, home: Geschwindigkeit (Einheiten/s).</translation>
    </message>
    <message numerus="yes">
        <source>%1 kbit/s: %n display(s)</source>
        <translation>
            <numerusform>%1 kbit/s: %n Anzeige</numerusform>
            <numerusform>%1 kbit/s: %n Anzeigen</numerusform>
        </translation>
    </message>
    <message>
        <source>no NM170/NM172/NM174 display answered at %1 bit/s</source>
        <translation>keine NM170/NM172/NM174-Anzeige hat bei %1 bit/s geantwortet</translation>
    </message>
    <message>
        <source>usage: nm17x URI oscillate NODE start|stop</source>
        <translation>Aufruf: nm17x URI oscillate KNOTEN start|stop</translation>
    </message>
    <message>
        <source>node %1: 204Dh:02</source>
        <translation>Knoten %1: 204Dh:02</translation>
    </message>
    <message>
        <source>node %1: oscillation %2</source>
        <translation>Knoten %1: Pendeln %2</translation>
    </message>
    <message>
        <source>nm17x scan: the bit rates to look at (default 125000,250000).</source>
        <translation>nm17x scan: die zu prüfenden Bitraten (Standard 125000,250000).</translation>
    </message>
    <message>
        <source>a value</source>
        <translation>ein Wert</translation>
    </message>
    <message>
        <source>home with the drive&apos;s homing method number, e.g. 35; prints the position</source>
        <translation>mit der Referenzfahrt-Methode des Antriebs referenzieren, z. B. 35; gibt die Position aus</translation>
    </message>
    <message>
        <source>run a motion block of the drive&apos;s table (or the sequence it starts) to its end; prints the position</source>
        <translation>einen Fahrsatz aus der Tabelle des Antriebs (oder die Folge, die er startet) bis zum Ende fahren; gibt die Position aus</translation>
    </message>
    <message>
        <source>travel: run the sequence that starts at BLOCK.</source>
        <translation>travel: die Fahrsatzfolge ab BLOCK fahren.</translation>
    </message>
    <message>
        <source>travel: resume the interrupted block.</source>
        <translation>travel: den unterbrochenen Fahrsatz wieder aufnehmen.</translation>
    </message>
    <message>
        <source>METHOD is a homing method number, not &apos;%1&apos;</source>
        <translation>METHODE ist die Nummer einer Referenzfahrtmethode, nicht „%1“</translation>
    </message>
    <message>
        <source>BLOCK is a motion block number, not &apos;%1&apos;</source>
        <translation>BLOCK ist eine Fahrsatznummer, nicht „%1“</translation>
    </message>
    <message>
        <source>--ram needs a vabus:// URI</source>
        <translation>--ram braucht eine vabus://-URI</translation>
    </message>
    <message>
        <source>writing %1</source>
        <translation>Schreiben von %1</translation>
    </message>
    <message>
        <source>  node %1: %2</source>
        <translation>  Knoten %1: %2</translation>
    </message>
    <message>
        <source>scanned nodes 1..127 on %1 in %2 ms</source>
        <translation>Knoten 1..127 an %1 in %2 ms abgefragt</translation>
    </message>
    <message>
        <source>nm17x settings: inputs F/G: standard, takten, externposi or off.</source>
        <translation>nm17x settings: Eingänge F/G: standard, takten, externposi oder off.</translation>
    </message>
    <message>
        <source>nm17x settings: keys: standard, slow, middle or fast.</source>
        <translation>nm17x settings: Tasten: standard, slow, middle oder fast.</translation>
    </message>
    <message>
        <source>nm17x settings: spindle pitch in mm per revolution (sets the scaling).</source>
        <translation>nm17x settings: Spindelsteigung in mm pro Umdrehung (setzt die Skalierung).</translation>
    </message>
    <message>
        <source>nm17x settings: sensor steps per revolution (default 2304; NM174 4096).</source>
        <translation>nm17x settings: Geberschritte pro Umdrehung (Standard 2304; NM174 4096).</translation>
    </message>
    <message>
        <source>nm17x settings: jump filter width in sensor steps.</source>
        <translation>nm17x settings: Breite des Sprungfilters in Geberschritten.</translation>
    </message>
    <message>
        <source>nm17x settings: jumps filtered before one is taken as real.</source>
        <translation>nm17x settings: gefilterte Sprünge, bevor einer als echt gilt.</translation>
    </message>
    <message>
        <source>nm17x settings: dynamic pre-shutdown on or off.</source>
        <translation>nm17x settings: dynamische Vorabschaltung on oder off.</translation>
    </message>
    <message>
        <source>usage: nm17x URI settings NODE [--input-mode M] [--key-mode M] [--pitch MM [--steps N]] [--filter-width STEPS] [--filter-count N] [--pre-shutdown on|off]</source>
        <translation>Aufruf: nm17x URI settings KNOTEN [--input-mode M] [--key-mode M] [--pitch MM [--steps N]] [--filter-width SCHRITTE] [--filter-count N] [--pre-shutdown on|off]</translation>
    </message>
    <message>
        <source>--input-mode takes standard, takten, externposi or off</source>
        <translation>--input-mode erwartet standard, takten, externposi oder off</translation>
    </message>
    <message>
        <source>--key-mode takes standard, slow, middle or fast</source>
        <translation>--key-mode erwartet standard, slow, middle oder fast</translation>
    </message>
    <message>
        <source>--pitch takes the spindle pitch in mm per revolution</source>
        <translation>--pitch erwartet die Spindelsteigung in mm pro Umdrehung</translation>
    </message>
    <message>
        <source>--%1 takes a number</source>
        <translation>--%1 erwartet eine Zahl</translation>
    </message>
    <message>
        <source>--pre-shutdown takes on or off</source>
        <translation>--pre-shutdown erwartet on oder off</translation>
    </message>
    <message>
        <source>node %1  %2</source>
        <translation>Knoten %1  %2</translation>
    </message>
    <message>
        <source>%1 = %2 mm/rev at %3 steps/rev</source>
        <translation>%1 = %2 mm/U bei %3 Schritten/U</translation>
    </message>
    <message>
        <source>drivebench-cli: warning: the axis is not known to be referenced (no homing seen, and the drive does not tell): positions count from the drive&apos;s present zero</source>
        <translation>drivebench-cli: Warnung: Es ist nicht bekannt, ob die Achse referenziert ist (keine Referenzfahrt gesehen, und der Antrieb sagt es nicht): Positionen zählen vom jetzigen Nullpunkt des Antriebs</translation>
    </message>
    <message>
        <source>%1 needs --vel V (signed) and --time MS</source>
        <translation>%1 braucht --vel V (mit Vorzeichen) und --time MS</translation>
    </message>
    <message>
        <source>drivebench-cli: warning: the drive has no profile position mode, so MC_MoveVelocity cannot move in leases, and nothing on the drive&apos;s side stops it if drivebench-cli dies on this connection</source>
        <translation>drivebench-cli: Warnung: Der Antrieb hat keinen Profile-Position-Modus, daher kann MC_MoveVelocity nicht in befristeten Abschnitten fahren, und nichts auf der Seite des Antriebs hält ihn an, wenn drivebench-cli auf dieser Verbindung ausfällt</translation>
    </message>
    <message>
        <source>couple the axis to its master at N:D (electronic gear) for MS ms, then uncouple; --out uncouples a running gear</source>
        <translation>die Achse für MS ms mit N:D an ihren Master kuppeln (elektronisches Getriebe), dann auskuppeln; --out kuppelt ein laufendes Getriebe aus</translation>
    </message>
    <message>
        <source>--ratio takes NUMERATOR:DENOMINATOR (e.g. 3:2), not &apos;%1&apos;</source>
        <translation>--ratio erwartet ZÄHLER:NENNER (z. B. 3:2), nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--ratio %1: the numerator must not be 0 and the denominator must be at least 1</source>
        <translation>--ratio %1: der Zähler darf nicht 0 sein, und der Nenner muss mindestens 1 sein</translation>
    </message>
    <message>
        <source>--%1 takes a ramp &gt;= 0 (units/s²)</source>
        <translation>--%1 erwartet eine Rampe &gt;= 0 (Einheiten/s²)</translation>
    </message>
    <message>
        <source>gear: slave turns per master turn, NUMERATOR:DENOMINATOR.</source>
        <translation>gear: Umdrehungen des Slaves je Umdrehung des Masters, ZÄHLER:NENNER.</translation>
    </message>
    <message>
        <source>gear: uncouple a gear started elsewhere.</source>
        <translation>gear: ein anderswo gestartetes Getriebe auskuppeln.</translation>
    </message>
    <message>
        <source>gear takes --ratio N:D --time MS, or --out</source>
        <translation>gear erwartet --ratio N:D --time MS oder --out</translation>
    </message>
    <message>
        <source>gear --ratio needs --time MS: how long the axis follows its master</source>
        <translation>gear --ratio braucht --time MS: wie lange die Achse ihrem Master folgt</translation>
    </message>
    <message>
        <source>--time takes ms &gt;= 0</source>
        <translation>--time erwartet ms &gt;= 0</translation>
    </message>
    <message>
        <source>in gear %1:%2 after %3 ms</source>
        <translation>eingekuppelt mit %1:%2 nach %3 ms</translation>
    </message>
    <message>
        <source>MC_GearOut: the axis did not stop within %1 ms (--wait); quick stop</source>
        <translation>MC_GearOut: die Achse hat nicht innerhalb von %1 ms angehalten (--wait); Schnellhalt</translation>
    </message>
    <message>
        <source>move, jog, home, gear: acceleration (units/s²).</source>
        <translation>move, jog, home, gear: Beschleunigung (Einheiten/s²).</translation>
    </message>
    <message>
        <source>move, jog, velocity, halt, stop, gear: deceleration (units/s²).</source>
        <translation>move, jog, velocity, halt, stop, gear: Verzögerung (Einheiten/s²).</translation>
    </message>
    <message>
        <source>jog, velocity, gear: how long to move (ms).</source>
        <translation>jog, velocity, gear: Fahrdauer (ms).</translation>
    </message>
    <message>
        <source>cannot check the device&apos;s serial number (1018h.4); --ignore-identity restores without the check</source>
        <translation>die Seriennummer des Geräts (1018h.4) lässt sich nicht prüfen; --ignore-identity stellt ohne die Prüfung wieder her</translation>
    </message>
    <message>
        <source>%1 was read from another unit (serial number %2), the device reports %3; give --ignore-identity to restore it to this unit</source>
        <translation>%1 wurde von einem anderen Exemplar gelesen (Seriennummer %2), das Gerät meldet %3; geben Sie --ignore-identity an, um ihn auf dieses Exemplar wiederherzustellen</translation>
    </message>
</context>
<context>
    <name>db::AddressFormat</name>
    <message>
        <source>&apos;%1&apos; is not a parameter address; write NUMBER:DATASET in decimal, e.g. 372:2 (a number alone is data set 0)</source>
        <translation>„%1“ ist keine Parameteradresse; NUMMER:DATENSATZ dezimal schreiben, z. B. 372:2 (eine Nummer allein ist Datensatz 0)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a parameter address: NUMBER:DATASET takes a parameter number of 0-65535 and a data set of 0-255, e.g. 372:2</source>
        <translation>„%1“ ist keine Parameteradresse: NUMMER:DATENSATZ erwartet eine Parameternummer 0-65535 und einen Datensatz 0-255, z. B. 372:2</translation>
    </message>
</context>
<context>
    <name>db::ChangeLog</name>
    <message>
        <source>not sent</source>
        <translation>nicht gesendet</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>write</source>
        <translation>schreiben</translation>
    </message>
    <message>
        <source>restore</source>
        <translation>wiederherstellen</translation>
    </message>
    <message>
        <source>store permanently</source>
        <translation>dauerhaft speichern</translation>
    </message>
    <message>
        <source>enable</source>
        <translation>freigeben</translation>
    </message>
    <message>
        <source>disable</source>
        <translation>sperren</translation>
    </message>
    <message>
        <source>motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <source>NMT</source>
        <translation>NMT</translation>
    </message>
    <message>
        <source>fault reset</source>
        <translation>Fehler quittieren</translation>
    </message>
    <message>
        <source>pending</source>
        <translation>offen</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>RAM only</source>
        <translation>nur RAM</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>RAM only, lost at power-off</source>
        <translation>nur RAM, beim Ausschalten verloren</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>CAN frame</source>
        <translation>CAN-Frame</translation>
    </message>
</context>
<context>
    <name>db::Cia301</name>
    <message>
        <source>no error / error reset</source>
        <translation>kein Fehler / Fehler zurückgesetzt</translation>
    </message>
    <message>
        <source>generic error</source>
        <translation>allgemeiner Fehler</translation>
    </message>
    <message>
        <source>current, device input side</source>
        <translation>Strom, Geräteeingang</translation>
    </message>
    <message>
        <source>current inside the device</source>
        <translation>Strom im Gerät</translation>
    </message>
    <message>
        <source>current, device output side</source>
        <translation>Strom, Geräteausgang</translation>
    </message>
    <message>
        <source>current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>mains voltage</source>
        <translation>Netzspannung</translation>
    </message>
    <message>
        <source>voltage inside the device</source>
        <translation>Spannung im Gerät</translation>
    </message>
    <message>
        <source>output voltage</source>
        <translation>Ausgangsspannung</translation>
    </message>
    <message>
        <source>voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>ambient temperature</source>
        <translation>Umgebungstemperatur</translation>
    </message>
    <message>
        <source>device temperature</source>
        <translation>Gerätetemperatur</translation>
    </message>
    <message>
        <source>temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>device hardware</source>
        <translation>Gerätehardware</translation>
    </message>
    <message>
        <source>internal software</source>
        <translation>interne Software</translation>
    </message>
    <message>
        <source>user software</source>
        <translation>Anwendersoftware</translation>
    </message>
    <message>
        <source>data set</source>
        <translation>Datensatz</translation>
    </message>
    <message>
        <source>device software</source>
        <translation>Gerätesoftware</translation>
    </message>
    <message>
        <source>additional modules</source>
        <translation>Zusatzmodule</translation>
    </message>
    <message>
        <source>communication</source>
        <translation>Kommunikation</translation>
    </message>
    <message>
        <source>CAN overrun (objects lost)</source>
        <translation>CAN-Überlauf (Objekte verloren)</translation>
    </message>
    <message>
        <source>CAN in error passive mode</source>
        <translation>CAN im Zustand Error Passive</translation>
    </message>
    <message>
        <source>life guard or heartbeat error</source>
        <translation>Life-Guarding- oder Heartbeat-Fehler</translation>
    </message>
    <message>
        <source>recovered from bus off</source>
        <translation>Bus-off behoben</translation>
    </message>
    <message>
        <source>protocol error</source>
        <translation>Protokollfehler</translation>
    </message>
    <message>
        <source>monitoring</source>
        <translation>Überwachung</translation>
    </message>
    <message>
        <source>external error</source>
        <translation>externer Fehler</translation>
    </message>
    <message>
        <source>additional functions</source>
        <translation>Zusatzfunktionen</translation>
    </message>
    <message>
        <source>device specific</source>
        <translation>gerätespezifisch</translation>
    </message>
    <message>
        <source>unknown error 0x%1</source>
        <translation>unbekannter Fehler 0x%1</translation>
    </message>
</context>
<context>
    <name>db::ConnectionHealth</name>
    <message>
        <source>the link to %1 closed</source>
        <translation>die Verbindung zu %1 wurde geschlossen</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>connecting…</source>
        <translation>verbinde…</translation>
    </message>
    <message>
        <source>waiting for the device to answer</source>
        <translation>warte auf Antwort des Geräts</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>not responding</source>
        <translation>antwortet nicht</translation>
    </message>
    <message>
        <source>connection failed</source>
        <translation>Verbindung fehlgeschlagen</translation>
    </message>
    <message>
        <source>connection lost</source>
        <translation>Verbindung verloren</translation>
    </message>
    <message>
        <source>disconnected by you</source>
        <translation>von Ihnen getrennt</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>db::Error</name>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>invalid argument</source>
        <translation>ungültiges Argument</translation>
    </message>
    <message>
        <source>out of range</source>
        <translation>außerhalb des Wertebereichs</translation>
    </message>
    <message>
        <source>access denied</source>
        <translation>Zugriff verweigert</translation>
    </message>
    <message>
        <source>not supported</source>
        <translation>nicht unterstützt</translation>
    </message>
    <message>
        <source>connection refused</source>
        <translation>Verbindung abgelehnt</translation>
    </message>
    <message>
        <source>host not found</source>
        <translation>Host nicht gefunden</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>Zeitüberschreitung</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>device error</source>
        <translation>Gerätefehler</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>i/o error</source>
        <translation>E/A-Fehler</translation>
    </message>
    <message>
        <source>busy</source>
        <translation>belegt</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>malformed data</source>
        <translation>fehlerhafte Daten</translation>
    </message>
</context>
<context>
    <name>db::ParameterBackup</name>
    <message>
        <source>no connection</source>
        <translation>keine Verbindung</translation>
    </message>
    <message>
        <source>backup cancelled after %1 of %2 objects</source>
        <translation>Sicherung nach %1 von %2 Objekten abgebrochen</translation>
    </message>
    <message>
        <source>the backup has not finished</source>
        <translation>die Sicherung ist nicht abgeschlossen</translation>
    </message>
    <message>
        <source>no object could be read (first: %1)</source>
        <translation>kein Objekt konnte gelesen werden (erstes: %1)</translation>
    </message>
    <message>
        <source>nothing to read: no readable object</source>
        <translation>nichts zu lesen: kein lesbares Objekt</translation>
    </message>
    <message>
        <source>no object could be read (%1 tried; first: %2)</source>
        <translation>kein Objekt konnte gelesen werden (%1 versucht; erstes: %2)</translation>
    </message>
    <message>
        <source>%1 of %2 objects could not be read (first: %3)</source>
        <translation>%1 von %2 Objekten konnten nicht gelesen werden (erstes: %3)</translation>
    </message>
    <message>
        <source>the connection was closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation>Lesen von %1</translation>
    </message>
    <message>
        <source>the device stopped answering; reading %1</source>
        <translation>das Gerät antwortet nicht mehr; Lesen von %1</translation>
    </message>
    <message>
        <source>the device answered an identity that is not a UNSIGNED32: %1</source>
        <translation>das Gerät hat eine Identität geantwortet, die kein UNSIGNED32 ist: %1</translation>
    </message>
    <message>
        <source>the device answered a value that is not a %1: %2</source>
        <translation>das Gerät hat einen Wert geantwortet, der kein %1 ist: %2</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
</context>
<context>
    <name>db::ParameterRestore</name>
    <message>
        <source>not in the device description</source>
        <translation>nicht in der Gerätebeschreibung</translation>
    </message>
    <message>
        <source>%1 object</source>
        <translation>%1 Objekt</translation>
    </message>
    <message>
        <source>nothing to restore: the parameter set holds no object</source>
        <translation>nichts wiederherzustellen: der Parametersatz enthält kein Objekt</translation>
    </message>
    <message>
        <source>nothing to restore: no selected object is in the set</source>
        <translation>nichts wiederherzustellen: kein ausgewähltes Objekt ist im Satz</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>restore cancelled</source>
        <translation>Wiederherstellung abgebrochen</translation>
    </message>
    <message>
        <source>the connection was closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
    <message>
        <source>writing %1</source>
        <translation>Schreiben von %1</translation>
    </message>
    <message>
        <source>write-only: not read back</source>
        <translation>nur schreibbar: nicht zurückgelesen</translation>
    </message>
    <message>
        <source>cancelled before the read-back</source>
        <translation>vor dem Rücklesen abgebrochen</translation>
    </message>
    <message>
        <source>PDO %1h not changed: reading its COB-ID failed: %2</source>
        <translation>PDO %1h nicht geändert: Lesen der COB-ID fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>mapping not changed: reading %1 failed: %2</source>
        <translation>Mapping nicht geändert: Lesen von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>PDO %1h could not be disabled: %2</source>
        <translation>PDO %1h konnte nicht deaktiviert werden: %2</translation>
    </message>
    <message>
        <source>mapping %1 could not be cleared: %2</source>
        <translation>Mapping %1 konnte nicht gelöscht werden: %2</translation>
    </message>
    <message>
        <source>writing back the previous value of %1 failed: %2</source>
        <translation>Zurückschreiben des vorherigen Werts von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>written, but the read-back failed: %1</source>
        <translation>geschrieben, aber das Rücklesen ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>reading back %1</source>
        <translation>Rücklesen von %1</translation>
    </message>
    <message>
        <source>read back %1, expected %2</source>
        <translation>zurückgelesen %1, erwartet %2</translation>
    </message>
    <message numerus="yes">
        <source>not stored: %n row(s) did not succeed</source>
        <translation>
            <numerusform>nicht gespeichert: %n Zeile nicht erfolgreich</numerusform>
            <numerusform>nicht gespeichert: %n Zeilen nicht erfolgreich</numerusform>
        </translation>
    </message>
    <message>
        <source>storing (1010h sub 1 = &quot;save&quot;) failed: %1</source>
        <translation>Speichern (1010h Sub 1 = „save“) fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>not stored: the restore stopped</source>
        <translation>nicht gespeichert: die Wiederherstellung wurde beendet</translation>
    </message>
    <message>
        <source>not attempted: %1</source>
        <translation>nicht versucht: %1</translation>
    </message>
    <message>
        <source>PDO %1h left disabled (COB-ID bit 31 set)</source>
        <translation>PDO %1h bleibt deaktiviert (COB-ID Bit 31 gesetzt)</translation>
    </message>
    <message>
        <source>the set&apos;s addresses are %1 addresses (like %2), the device&apos;s are %3 addresses (like %4): it is not a set for this device</source>
        <translation>die Adressen des Satzes sind %1-Adressen (wie %2), die des Geräts %3-Adressen (wie %4): es ist kein Satz für dieses Gerät</translation>
    </message>
</context>
<context>
    <name>db::ParameterSet</name>
    <message>
        <source>%1 has %2 addresses (like %3) but %4 has %5 addresses (like %6): the same address names different objects, so they cannot be compared</source>
        <translation>%1 hat %2-Adressen (wie %3), aber %4 hat %5-Adressen (wie %6): dieselbe Adresse bezeichnet verschiedene Objekte, daher ist kein Vergleich möglich</translation>
    </message>
</context>
<context>
    <name>db::StatusSource</name>
    <message>
        <source>Not ready to switch on</source>
        <translation>Nicht einschaltbereit</translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation>Einschaltsperre</translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation>Einschaltbereit</translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation>Eingeschaltet</translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation>Betrieb freigegeben</translation>
    </message>
    <message>
        <source>Quick stop active</source>
        <translation>Schnellhalt aktiv</translation>
    </message>
    <message>
        <source>Fault reaction active</source>
        <translation>Fehlerreaktion aktiv</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <source>Unknown state</source>
        <translation>Unbekannter Zustand</translation>
    </message>
</context>
<context>
    <name>db::TextLanguage</name>
    <message>
        <source>en</source>
        <comment>The code of this translation&apos;s language (de, fr, ...): device descriptions show the names they have in it.</comment>
        <translation>de</translation>
    </message>
</context>
<context>
    <name>db::bonfiglioli</name>
    <message>
        <source>configuration %1 has no positioning control (30 is not x40): velocity mode (rpm) only</source>
        <translation>Konfiguration %1 hat keine Lageregelung (30 ist nicht x40): nur Drehzahlmodus (1/min)</translation>
    </message>
    <message>
        <source>Link watchdog off (388 = 0): the inverter keeps running when the link stops.</source>
        <translation>Verbindungsüberwachung aus (388 = 0): der Umrichter läuft weiter, wenn die Verbindung abbricht.</translation>
    </message>
    <message>
        <source>fault F2714</source>
        <translation>Störung F2714</translation>
    </message>
    <message>
        <source>switch off</source>
        <translation>Abschalten</translation>
    </message>
    <message>
        <source>quick stop</source>
        <translation>Schnellhalt</translation>
    </message>
    <message>
        <source>stop, then fault F2714</source>
        <translation>Stillsetzen, dann Störung F2714</translation>
    </message>
    <message>
        <source>quick stop, then fault F2714</source>
        <translation>Schnellhalt, dann Störung F2714</translation>
    </message>
    <message>
        <source>Link watchdog (388 = %1): %2 10 s after the last exchange.</source>
        <translation>Verbindungsüberwachung (388 = %1): %2 10 s nach dem letzten Datenaustausch.</translation>
    </message>
    <message>
        <source>No answer for %1 s: the inverter reacts in %2 s at the latest.</source>
        <translation>Seit %1 s keine Antwort: der Umrichter reagiert spätestens in %2 s.</translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation>Verbindung geschlossen</translation>
    </message>
    <message>
        <source>the inverter did not give its configuration (30)</source>
        <translation>der Umrichter hat seine Konfiguration (30) nicht geliefert</translation>
    </message>
    <message>
        <source>superseded by %1</source>
        <translation>ersetzt durch %1</translation>
    </message>
    <message>
        <source>the inverter is not in &apos;operation enabled&apos;: enable it first</source>
        <translation>der Umrichter ist nicht in &apos;Betrieb freigegeben&apos;: zuerst freigeben</translation>
    </message>
    <message>
        <source>refused: mode change while moving</source>
        <translation>verweigert: Betriebsartwechsel während der Bewegung</translation>
    </message>
    <message>
        <source>the inverter did not go to &apos;switched on&apos; for the mode change</source>
        <translation>der Umrichter ist für den Betriebsartwechsel nicht nach &apos;Eingeschaltet&apos; gegangen</translation>
    </message>
    <message>
        <source>the inverter did not return to &apos;operation enabled&apos;</source>
        <translation>der Umrichter ist nicht nach &apos;Betrieb freigegeben&apos; zurückgekehrt</translation>
    </message>
    <message>
        <source>enable</source>
        <translation>Freigabe</translation>
    </message>
    <message>
        <source>disable</source>
        <translation>Sperren</translation>
    </message>
    <message>
        <source>the inverter did not go to &apos;switch on disabled&apos;</source>
        <translation>der Umrichter ist nicht nach &apos;Einschalten gesperrt&apos; gegangen</translation>
    </message>
    <message>
        <source>the inverter is in fault: reset it first</source>
        <translation>der Umrichter ist in Störung: zuerst quittieren</translation>
    </message>
    <message>
        <source>the inverter did not go to &apos;ready to switch on&apos;</source>
        <translation>der Umrichter ist nicht nach &apos;Einschaltbereit&apos; gegangen</translation>
    </message>
    <message>
        <source>no mains voltage (status bit 4 &apos;voltage enabled&apos; is 0): the inverter cannot switch on</source>
        <translation>keine Netzspannung (Zustandsbit 4 &apos;Spannung freigegeben&apos; ist 0): der Umrichter kann nicht einschalten</translation>
    </message>
    <message>
        <source>the inverter did not go to &apos;switched on&apos;</source>
        <translation>der Umrichter ist nicht nach &apos;Eingeschaltet&apos; gegangen</translation>
    </message>
    <message>
        <source>the hardware enable (STO) is off: the inverter stays in &apos;switched on&apos;</source>
        <translation>die Hardware-Freigabe (STO) fehlt: der Umrichter bleibt in &apos;Eingeschaltet&apos;</translation>
    </message>
    <message>
        <source>fault reset</source>
        <translation>Störungsquittierung</translation>
    </message>
    <message>
        <source>the fault stays after the reset: remove its cause first</source>
        <translation>die Störung bleibt nach dem Quittieren: zuerst die Ursache beheben</translation>
    </message>
    <message>
        <source>target -1 u cannot be approached: 1455 = -1 switches the override off</source>
        <translation>Ziel -1 u kann nicht angefahren werden: 1455 = -1 schaltet den Override ab</translation>
    </message>
    <message>
        <source>profile position</source>
        <translation>Profillage</translation>
    </message>
    <message>
        <source>the inverter did not clear &apos;set-point acknowledged&apos; (bit 12)</source>
        <translation>der Umrichter hat &apos;Sollwert bestätigt&apos; (Bit 12) nicht zurückgesetzt</translation>
    </message>
    <message>
        <source>the inverter did not acknowledge the set-point (bit 12)</source>
        <translation>der Umrichter hat den Sollwert nicht bestätigt (Bit 12)</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>velocity -1 cannot be set: -1 switches the override off</source>
        <translation>Geschwindigkeit -1 kann nicht vorgegeben werden: -1 schaltet den Override ab</translation>
    </message>
    <message>
        <source>halt</source>
        <translation>Halt</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <source>homing not finished within %1 s</source>
        <translation>Referenzfahrt nicht innerhalb von %1 s beendet</translation>
    </message>
    <message>
        <source>homing error (status bit 13)</source>
        <translation>Referenzfahrt-Fehler (Zustandsbit 13)</translation>
    </message>
    <message>
        <source>the ACTIVE Cube has no torque mode over the override</source>
        <translation>der ACTIVE Cube hat keinen Drehmomentmodus über den Override</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>motion block %1 does not exist (1-32)</source>
        <translation>Fahrsatz %1 gibt es nicht (1-32)</translation>
    </message>
    <message>
        <source>table travel block %1</source>
        <translation>Fahrsatz %1</translation>
    </message>
    <message>
        <source>the inverter did not start the motion block (status bit 8)</source>
        <translation>der Umrichter hat den Fahrsatz nicht gestartet (Zustandsbit 8)</translation>
    </message>
    <message>
        <source>the motion block did not end within %1 s</source>
        <translation>der Fahrsatz wurde nicht innerhalb von %1 s beendet</translation>
    </message>
    <message>
        <source>move away from limit switch</source>
        <translation>Endschalter freifahren</translation>
    </message>
    <message>
        <source>the limit switch was not cleared</source>
        <translation>der Endschalter wurde nicht freigefahren</translation>
    </message>
    <message>
        <source>writing %1</source>
        <translation>Schreiben von %1</translation>
    </message>
    <message>
        <source>the inverter went to fault (status word 0x%1)</source>
        <translation>der Umrichter ist in Störung gegangen (Zustandswort 0x%1)</translation>
    </message>
    <message>
        <source>electronic gear</source>
        <translation>elektronisches Getriebe</translation>
    </message>
    <message>
        <source>the inverter did not report &apos;in gear&apos; (status bit 10) within %1 s</source>
        <translation>der Umrichter hat nicht innerhalb von %1 s „eingekuppelt“ (Statusbit 10) gemeldet</translation>
    </message>
    <message>
        <source>gear ratio %1:%2: the numerator must not be 0 and the denominator must be at least 1</source>
        <translation>Getriebeübersetzung %1:%2: der Zähler darf nicht 0 sein, und der Nenner muss mindestens 1 sein</translation>
    </message>
    <message>
        <source>not coupled: the inverter is not in electronic gear mode (1454 = -3)</source>
        <translation>nicht eingekuppelt: der Umrichter ist nicht in der Betriebsart elektronisches Getriebe (1454 = -3)</translation>
    </message>
    <message>
        <source>leaving the electronic gear</source>
        <translation>Verlassen des elektronischen Getriebes</translation>
    </message>
    <message>
        <source>the connection has no status source</source>
        <translation>die Verbindung hat keine Statusquelle</translation>
    </message>
    <message>
        <source>411 was not read</source>
        <translation>411 wurde nicht gelesen</translation>
    </message>
    <message>
        <source>no answer within %1 ms: the inverter did not report its state</source>
        <translation>keine Antwort innerhalb von %1 ms: der Umrichter meldete seinen Zustand nicht</translation>
    </message>
</context>
<context>
    <name>db::bonfiglioli::AcuStatusSource</name>
    <message>
        <source>Status word (411):</source>
        <translation>Zustandswort (411):</translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation>Ziel erreicht</translation>
    </message>
    <message>
        <source>Mains on</source>
        <translation>Netz ein</translation>
    </message>
    <message>
        <source>Remote</source>
        <translation>Fernsteuerung</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Warning 2</source>
        <translation>Warnung 2</translation>
    </message>
    <message>
        <source>Internal limit</source>
        <translation>Interne Begrenzung</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <source>Current fault (260):</source>
        <translation>Aktueller Fehler (260):</translation>
    </message>
    <message>
        <source>No fault</source>
        <translation>Kein Fehler</translation>
    </message>
    <message>
        <source>Fault %1 (not in the fault table)</source>
        <translation>Fehler %1 (nicht in der Fehlertabelle)</translation>
    </message>
    <message>
        <source>%1 bit %2</source>
        <translation>%1 Bit %2</translation>
    </message>
    <message>
        <source>When the link stops for 10 s the inverter reacts as parameter 388 says (not read yet).</source>
        <translation>Steht die Verbindung 10 s still, reagiert der Umrichter wie in Parameter 388 eingestellt (noch nicht gelesen).</translation>
    </message>
    <message>
        <source>keeps its operating point</source>
        <translation>behält seinen Arbeitspunkt</translation>
    </message>
    <message>
        <source>goes to fault F2714 at once</source>
        <translation>geht sofort in Störung F2714</translation>
    </message>
    <message>
        <source>switches off (disable voltage, then switch on disabled)</source>
        <translation>schaltet ab (Spannung sperren, dann Einschaltsperre)</translation>
    </message>
    <message>
        <source>makes a quick stop, then switch on disabled</source>
        <translation>macht einen Schnellhalt, dann Einschaltsperre</translation>
    </message>
    <message>
        <source>stops, then goes to fault F2714</source>
        <translation>hält an und geht dann in Störung F2714</translation>
    </message>
    <message>
        <source>makes a quick stop, then goes to fault F2714</source>
        <translation>macht einen Schnellhalt und geht dann in Störung F2714</translation>
    </message>
    <message>
        <source>reacts in a way this program does not know</source>
        <translation>reagiert auf eine diesem Programm unbekannte Weise</translation>
    </message>
    <message>
        <source>When the link stops for 10 s the inverter %1 (parameter 388 = %2).</source>
        <translation>Steht die Verbindung 10 s still, %1 der Umrichter (Parameter 388 = %2).</translation>
    </message>
</context>
<context>
    <name>db::canopen</name>
    <message>
        <source>%1 is not a CANopen URI (canopen+socketcan://, canopen+virtualcan://, canopen+slcan://)</source>
        <translation>%1 ist keine CANopen-URI (canopen+socketcan://, canopen+virtualcan://, canopen+slcan://)</translation>
    </message>
    <message>
        <source>%1 names no %2</source>
        <translation>%1 nennt kein %2</translation>
    </message>
    <message>
        <source>%1 did not open within %2 ms</source>
        <translation>%1 wurde nicht innerhalb von %2 ms geöffnet</translation>
    </message>
    <message>
        <source>%1 is already in use at %2 bit/s, not %3 bit/s</source>
        <translation>%1 wird bereits mit %2 Bit/s benutzt, nicht mit %3 Bit/s</translation>
    </message>
    <message>
        <source>connection to node %1 deleted</source>
        <translation>Verbindung zu Knoten %1 gelöscht</translation>
    </message>
    <message>
        <source>%1 needs the node id: ?node=N (1..127)</source>
        <translation>%1 braucht die Knoten-ID: ?node=N (1..127)</translation>
    </message>
    <message>
        <source>unknown SDO mode &apos;%1&apos; (auto, expedited, segmented or block)</source>
        <translation>unbekannter SDO-Modus „%1“ (auto, expedited, segmented oder block)</translation>
    </message>
    <message>
        <source>connection to node %1 closed</source>
        <translation>Verbindung zu Knoten %1 geschlossen</translation>
    </message>
    <message>
        <source>node %1 does not answer on %2 (no SDO answer to 1000h within %3 ms)</source>
        <translation>Knoten %1 antwortet nicht auf %2 (keine SDO-Antwort auf 1000h innerhalb von %3 ms)</translation>
    </message>
    <message>
        <source>CAN bus %1 closed</source>
        <translation>CAN-Bus %1 geschlossen</translation>
    </message>
    <message>
        <source>cannot write a %1 to an object of unknown type (give its type)</source>
        <translation>ein %1 kann nicht in ein Objekt unbekannten Typs geschrieben werden (Typ angeben)</translation>
    </message>
    <message>
        <source>EMCY from node %1 has %2 bytes, needs at least 3</source>
        <translation>EMCY von Knoten %1 hat %2 Bytes, braucht mindestens 3</translation>
    </message>
    <message>
        <source>another LSS service is running</source>
        <translation>ein anderer LSS-Dienst läuft</translation>
    </message>
    <message>
        <source>CAN bus %1 is not open</source>
        <translation>CAN-Bus %1 ist nicht geöffnet</translation>
    </message>
    <message>
        <source>LSS node id %1 is not 1..127</source>
        <translation>LSS-Knoten-ID %1 liegt nicht in 1..127</translation>
    </message>
    <message>
        <source>0x%1 is no LSS inquire service</source>
        <translation>0x%1 ist kein LSS-Abfragedienst</translation>
    </message>
    <message>
        <source>no unconfigured LSS slave answered the fastscan</source>
        <translation>kein unkonfigurierter LSS-Slave hat auf den Fastscan geantwortet</translation>
    </message>
    <message>
        <source>the LSS slave stopped answering during fastscan</source>
        <translation>der LSS-Slave hat während des Fastscans aufgehört zu antworten</translation>
    </message>
    <message>
        <source>LSS slave refused (error code %1%2)</source>
        <translation>LSS-Slave hat abgelehnt (Fehlercode %1%2)</translation>
    </message>
    <message>
        <source>no LSS answer (cs 0x%1) within %2 ms on %3</source>
        <translation>keine LSS-Antwort (cs 0x%1) innerhalb von %2 ms auf %3</translation>
    </message>
    <message>
        <source>PDO number %1 out of range</source>
        <translation>PDO-Nummer %1 außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>%1: %2 bits mapped, a CAN frame carries 64</source>
        <translation>%1: %2 Bit gemappt, ein CAN-Frame trägt 64</translation>
    </message>
    <message>
        <source>configuring PDO, writing</source>
        <translation>konfiguriere PDO, schreibe</translation>
    </message>
    <message>
        <source>%1 carries %2 bytes, its mapping needs %3</source>
        <translation>%1 überträgt %2 Bytes, sein Mapping braucht %3</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>SDO client deleted</source>
        <translation>SDO-Client gelöscht</translation>
    </message>
    <message>
        <source>expedited SDO download carries 1 to 4 bytes, not %1</source>
        <translation>ein expedited SDO-Download überträgt 1 bis 4 Bytes, nicht %1</translation>
    </message>
    <message>
        <source>node id %1 is outside 1..127</source>
        <translation>Knoten-ID %1 liegt außerhalb von 1..127</translation>
    </message>
    <message>
        <source>%1 in %2 (sent SDO abort 0x%3)</source>
        <translation>%1 in %2 (SDO-Abbruch 0x%3 gesendet)</translation>
    </message>
    <message>
        <source>object %1 does not exist</source>
        <translation>Objekt %1 existiert nicht</translation>
    </message>
    <message>
        <source>node %1 did not answer %2 within %3 ms</source>
        <translation>Knoten %1 hat auf %2 nicht innerhalb von %3 ms geantwortet</translation>
    </message>
    <message>
        <source>6007h = 3, quick stop</source>
        <translation>6007h = 3, Schnellhalt</translation>
    </message>
    <message>
        <source>no 6007h: the drive&apos;s own reaction</source>
        <translation>kein 6007h: die eigene Reaktion des Antriebs</translation>
    </message>
    <message>
        <source>drive stops within %1 ms if drivebench stops (our heartbeat from node %2 every %3 ms, watched by the drive&apos;s 1016h; %4)</source>
        <translation>Antrieb hält innerhalb von %1 ms an, wenn drivebench ausfällt (unser Heartbeat von Knoten %2 alle %3 ms, überwacht durch 1016h des Antriebs; %4)</translation>
    </message>
    <message>
        <source>drive stops within %1 ms if drivebench stops (node guarding every %2 ms, life time %1 ms; %3)</source>
        <translation>Antrieb hält innerhalb von %1 ms an, wenn drivebench ausfällt (Node Guarding alle %2 ms, Lebensdauer %1 ms; %3)</translation>
    </message>
    <message>
        <source>no drive-side supervision: node %1 describes neither 1016h nor 100Ch/100Dh; only the motion lease bounds a jog</source>
        <translation>keine antriebsseitige Überwachung: Knoten %1 beschreibt weder 1016h noch 100Ch/100Dh; nur die Bewegungsfreigabe begrenzt das Tippen</translation>
    </message>
    <message>
        <source>no drive-side supervision on this connection; only the motion lease bounds a jog</source>
        <translation>keine antriebsseitige Überwachung auf dieser Verbindung; nur die Bewegungsfreigabe begrenzt das Tippen</translation>
    </message>
    <message>
        <source>node %1 did not report its identity (%2: %3)</source>
        <translation>Knoten %1 hat seine Identität nicht gemeldet (%2: %3)</translation>
    </message>
    <message>
        <source>heartbeat lost: node %1 silent for more than %2 ms</source>
        <translation>Heartbeat verloren: Knoten %1 seit mehr als %2 ms still</translation>
    </message>
    <message>
        <source>connected to node %1 on %2</source>
        <translation>mit Knoten %1 an %2 verbunden</translation>
    </message>
    <message>
        <source>disconnected from %1</source>
        <translation>Verbindung zu %1 getrennt</translation>
    </message>
    <message>
        <source>setting up drive-side supervision</source>
        <translation>Einrichten der antriebsseitigen Überwachung</translation>
    </message>
    <message>
        <source>restoring the drive&apos;s supervision settings</source>
        <translation>Wiederherstellen der Überwachungseinstellungen des Antriebs</translation>
    </message>
</context>
<context>
    <name>db::canopen::FrameDecoder</name>
    <message>
        <source>all nodes</source>
        <translation>alle Knoten</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>pre-operational</source>
        <translation>Pre-Operational</translation>
    </message>
    <message>
        <source>reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>reset communication</source>
        <translation>Reset Kommunikation</translation>
    </message>
    <message>
        <source>command %1</source>
        <translation>Befehl %1</translation>
    </message>
    <message>
        <source>switch state global</source>
        <translation>Zustand global umschalten</translation>
    </message>
    <message>
        <source>configure node-id</source>
        <translation>Node-ID konfigurieren</translation>
    </message>
    <message>
        <source>configure bit timing</source>
        <translation>Bit-Timing konfigurieren</translation>
    </message>
    <message>
        <source>activate bit timing</source>
        <translation>Bit-Timing aktivieren</translation>
    </message>
    <message>
        <source>store configuration</source>
        <translation>Konfiguration speichern</translation>
    </message>
    <message>
        <source>switch state selective</source>
        <translation>Zustand selektiv umschalten</translation>
    </message>
    <message>
        <source>switch state selective response</source>
        <translation>Antwort auf selektives Umschalten</translation>
    </message>
    <message>
        <source>identify non-configured</source>
        <translation>Nicht konfigurierte identifizieren</translation>
    </message>
    <message>
        <source>identify slave</source>
        <translation>Slave identifizieren</translation>
    </message>
    <message>
        <source>fastscan</source>
        <translation>Fastscan</translation>
    </message>
    <message>
        <source>inquire vendor-id</source>
        <translation>Hersteller-ID abfragen</translation>
    </message>
    <message>
        <source>inquire product code</source>
        <translation>Produktcode abfragen</translation>
    </message>
    <message>
        <source>inquire revision</source>
        <translation>Revision abfragen</translation>
    </message>
    <message>
        <source>inquire serial number</source>
        <translation>Seriennummer abfragen</translation>
    </message>
    <message>
        <source>inquire node-id</source>
        <translation>Node-ID abfragen</translation>
    </message>
    <message>
        <source>TIME (%1 bytes)</source>
        <translation>TIME (%1 Bytes)</translation>
    </message>
    <message>
        <source>device specific</source>
        <translation>gerätespezifisch</translation>
    </message>
    <message>
        <source>additional functions</source>
        <translation>Zusatzfunktionen</translation>
    </message>
    <message>
        <source>error reset</source>
        <translation>Fehler zurückgesetzt</translation>
    </message>
    <message>
        <source>generic</source>
        <translation>allgemein</translation>
    </message>
    <message>
        <source>current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>device hardware</source>
        <translation>Gerätehardware</translation>
    </message>
    <message>
        <source>device software</source>
        <translation>Gerätesoftware</translation>
    </message>
    <message>
        <source>additional modules</source>
        <translation>Zusatzmodule</translation>
    </message>
    <message>
        <source>monitoring</source>
        <translation>Überwachung</translation>
    </message>
    <message>
        <source>external error</source>
        <translation>externer Fehler</translation>
    </message>
    <message>
        <source>error frame</source>
        <translation>Error-Frame</translation>
    </message>
    <message>
        <source>extended frame (not CANopen)</source>
        <translation>Extended-Frame (kein CANopen)</translation>
    </message>
    <message>
        <source>SYNC counter %1</source>
        <translation>SYNC Zähler %1</translation>
    </message>
    <message>
        <source>%1 node %2: remote request</source>
        <translation>%1 Knoten %2: Remote-Anfrage</translation>
    </message>
    <message>
        <source>Node guarding request node %1</source>
        <translation>Node-Guarding-Anfrage Knoten %1</translation>
    </message>
    <message>
        <source>Heartbeat node %1: no data</source>
        <translation>Heartbeat Knoten %1: keine Daten</translation>
    </message>
    <message>
        <source>Boot-up node %1</source>
        <translation>Boot-up Knoten %1</translation>
    </message>
    <message>
        <source>Heartbeat node %1: %2</source>
        <translation>Heartbeat Knoten %1: %2</translation>
    </message>
    <message>
        <source>LSS master: %1</source>
        <translation>LSS Master: %1</translation>
    </message>
    <message>
        <source>LSS slave: %1</source>
        <translation>LSS Slave: %1</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>keine Daten</translation>
    </message>
    <message>
        <source>NMT malformed (%1 bytes)</source>
        <translation>NMT fehlerhaft (%1 Bytes)</translation>
    </message>
    <message>
        <source>EMCY node %1: malformed (%2 bytes)</source>
        <translation>EMCY Knoten %1: fehlerhaft (%2 Bytes)</translation>
    </message>
    <message>
        <source>EMCY node %1: %2, reg %3</source>
        <translation>EMCY Knoten %1: %2, Reg. %3</translation>
    </message>
    <message>
        <source>, data %1</source>
        <translation>, Daten %1</translation>
    </message>
    <message>
        <source>%1 node %2</source>
        <translation>%1 Knoten %2</translation>
    </message>
    <message>
        <source>%1: %2 bytes</source>
        <translation>%1: %2 Bytes</translation>
    </message>
    <message>
        <source>%1 node %2: </source>
        <translation>%1 Knoten %2: </translation>
    </message>
    <message>
        <source>empty frame</source>
        <translation>leerer Frame</translation>
    </message>
    <message>
        <source>block segment %1%2 %3: %4</source>
        <translation>Blocksegment %1%2 %3: %4</translation>
    </message>
    <message>
        <source> last</source>
        <translation> letztes</translation>
    </message>
    <message>
        <source>abort %1: 0x%2 %3</source>
        <translation>Abbruch %1: 0x%2 %3</translation>
    </message>
    <message>
        <source>download %1 ← %2</source>
        <translation>Download %1 ← %2</translation>
    </message>
    <message>
        <source>download %1, %2 bytes</source>
        <translation>Download %1, %2 Bytes</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>download segment %1 %2%3: %4</source>
        <translation>Download-Segment %1 %2%3: %4</translation>
    </message>
    <message>
        <source>upload %1</source>
        <translation>Upload %1</translation>
    </message>
    <message>
        <source>upload segment request %1 %2</source>
        <translation>Upload-Segment-Anfrage %1 %2</translation>
    </message>
    <message>
        <source>block upload %1, blksize %2</source>
        <translation>Block-Upload %1, blksize %2</translation>
    </message>
    <message>
        <source>block upload start %1</source>
        <translation>Block-Upload Start %1</translation>
    </message>
    <message>
        <source>block upload ack %1: seq %2, blksize %3</source>
        <translation>Block-Upload Quittung %1: seq %2, blksize %3</translation>
    </message>
    <message>
        <source>block upload end %1 ok</source>
        <translation>Block-Upload Ende %1 ok</translation>
    </message>
    <message>
        <source>block download %1, %2 bytes</source>
        <translation>Block-Download %1, %2 Bytes</translation>
    </message>
    <message>
        <source>block download end %1, %2 unused, crc 0x%3</source>
        <translation>Block-Download Ende %1, %2 ungenutzt, crc 0x%3</translation>
    </message>
    <message>
        <source>unknown command 0x%1</source>
        <translation>unbekannter Befehl 0x%1</translation>
    </message>
    <message>
        <source>download %1 ok</source>
        <translation>Download %1 ok</translation>
    </message>
    <message>
        <source>download segment %1 %2 ok</source>
        <translation>Download-Segment %1 %2 ok</translation>
    </message>
    <message>
        <source>upload %1 → %2</source>
        <translation>Upload %1 → %2</translation>
    </message>
    <message>
        <source>upload %1, %2 bytes</source>
        <translation>Upload %1, %2 Bytes</translation>
    </message>
    <message>
        <source>upload segment %1 %2%3: %4</source>
        <translation>Upload-Segment %1 %2%3: %4</translation>
    </message>
    <message>
        <source>block download %1 ok, blksize %2</source>
        <translation>Block-Download %1 ok, blksize %2</translation>
    </message>
    <message>
        <source>block download ack %1: seq %2, blksize %3</source>
        <translation>Block-Download Quittung %1: seq %2, blksize %3</translation>
    </message>
    <message>
        <source>block download end %1 ok</source>
        <translation>Block-Download Ende %1 ok</translation>
    </message>
    <message>
        <source>block upload %1, %2 bytes</source>
        <translation>Block-Upload %1, %2 Bytes</translation>
    </message>
    <message>
        <source>block upload end %1, %2 unused, crc 0x%3</source>
        <translation>Block-Upload Ende %1, %2 ungenutzt, crc 0x%3</translation>
    </message>
</context>
<context>
    <name>db::canopen::NmtAnswer</name>
    <message>
        <source>not confirmed: node %1 sends no heartbeat</source>
        <translation>nicht bestätigt: Knoten %1 sendet keinen Heartbeat</translation>
    </message>
    <message>
        <source>no answer: node %1 sent no heartbeat within %2 ms</source>
        <translation>keine Antwort: Knoten %1 sandte innerhalb von %2 ms keinen Heartbeat</translation>
    </message>
    <message>
        <source>node %1 did not follow: it stays %2</source>
        <translation>Knoten %1 ist nicht gefolgt: er bleibt %2</translation>
    </message>
</context>
<context>
    <name>db::canopen::SdoAbort</name>
    <message>
        <source>toggle bit not alternated</source>
        <translation>Toggle-Bit nicht gewechselt</translation>
    </message>
    <message>
        <source>SDO protocol timed out</source>
        <translation>Zeitüberschreitung im SDO-Protokoll</translation>
    </message>
    <message>
        <source>client/server command specifier not valid or unknown</source>
        <translation>Client/Server-Befehlskennung ungültig oder unbekannt</translation>
    </message>
    <message>
        <source>invalid block size (block mode only)</source>
        <translation>ungültige Blockgröße (nur Blockmodus)</translation>
    </message>
    <message>
        <source>invalid sequence number (block mode only)</source>
        <translation>ungültige Sequenznummer (nur Blockmodus)</translation>
    </message>
    <message>
        <source>CRC error (block mode only)</source>
        <translation>CRC-Fehler (nur Blockmodus)</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>Speicher erschöpft</translation>
    </message>
    <message>
        <source>unsupported access to an object</source>
        <translation>nicht unterstützter Zugriff auf ein Objekt</translation>
    </message>
    <message>
        <source>attempt to read a write only object</source>
        <translation>Versuch, ein nur schreibbares Objekt zu lesen</translation>
    </message>
    <message>
        <source>attempt to write a read only object</source>
        <translation>Versuch, ein nur lesbares Objekt zu schreiben</translation>
    </message>
    <message>
        <source>object does not exist in the object dictionary</source>
        <translation>Objekt existiert nicht im Objektverzeichnis</translation>
    </message>
    <message>
        <source>object cannot be mapped to the PDO</source>
        <translation>Objekt kann nicht auf das PDO gemappt werden</translation>
    </message>
    <message>
        <source>the number and length of the objects to be mapped would exceed the PDO length</source>
        <translation>Anzahl und Länge der zu mappenden Objekte würden die PDO-Länge überschreiten</translation>
    </message>
    <message>
        <source>general parameter incompatibility</source>
        <translation>allgemeine Parameter-Inkompatibilität</translation>
    </message>
    <message>
        <source>general internal incompatibility in the device</source>
        <translation>allgemeine interne Inkompatibilität im Gerät</translation>
    </message>
    <message>
        <source>access failed due to a hardware error</source>
        <translation>Zugriff wegen eines Hardwarefehlers fehlgeschlagen</translation>
    </message>
    <message>
        <source>data type does not match, length of service parameter does not match</source>
        <translation>Datentyp passt nicht, Länge des Dienstparameters passt nicht</translation>
    </message>
    <message>
        <source>data type does not match, length of service parameter too high</source>
        <translation>Datentyp passt nicht, Länge des Dienstparameters zu groß</translation>
    </message>
    <message>
        <source>data type does not match, length of service parameter too low</source>
        <translation>Datentyp passt nicht, Länge des Dienstparameters zu klein</translation>
    </message>
    <message>
        <source>sub-index does not exist</source>
        <translation>Subindex existiert nicht</translation>
    </message>
    <message>
        <source>invalid value for parameter (download only)</source>
        <translation>ungültiger Wert für den Parameter (nur Download)</translation>
    </message>
    <message>
        <source>value of parameter written too high (download only)</source>
        <translation>geschriebener Parameterwert zu groß (nur Download)</translation>
    </message>
    <message>
        <source>value of parameter written too low (download only)</source>
        <translation>geschriebener Parameterwert zu klein (nur Download)</translation>
    </message>
    <message>
        <source>maximum value is less than minimum value</source>
        <translation>Maximalwert ist kleiner als Minimalwert</translation>
    </message>
    <message>
        <source>resource not available: SDO connection</source>
        <translation>Ressource nicht verfügbar: SDO-Verbindung</translation>
    </message>
    <message>
        <source>general error</source>
        <translation>allgemeiner Fehler</translation>
    </message>
    <message>
        <source>data cannot be transferred or stored to the application</source>
        <translation>Daten können nicht an die Anwendung übertragen oder dort gespeichert werden</translation>
    </message>
    <message>
        <source>data cannot be transferred or stored to the application because of local control</source>
        <translation>Daten können wegen lokaler Steuerung nicht an die Anwendung übertragen oder dort gespeichert werden</translation>
    </message>
    <message>
        <source>data cannot be transferred or stored to the application because of the present device state</source>
        <translation>Daten können im aktuellen Gerätezustand nicht an die Anwendung übertragen oder dort gespeichert werden</translation>
    </message>
    <message>
        <source>object dictionary dynamic generation fails or no object dictionary is present</source>
        <translation>dynamische Erzeugung des Objektverzeichnisses fehlgeschlagen oder kein Objektverzeichnis vorhanden</translation>
    </message>
    <message>
        <source>no data available</source>
        <translation>keine Daten verfügbar</translation>
    </message>
    <message>
        <source>unknown abort code 0x%1</source>
        <translation>unbekannter Abbruchcode 0x%1</translation>
    </message>
</context>
<context>
    <name>db::cia402</name>
    <message>
        <source>scaling object %1 is missing or zero</source>
        <translation>Skalierungsobjekt %1 fehlt oder ist null</translation>
    </message>
    <message>
        <source>%1: %2 did not happen within %3 ms (statusword 0x%4)</source>
        <translation>%1: %2 ist nicht innerhalb von %3 ms eingetreten (Statuswort 0x%4)</translation>
    </message>
    <message>
        <source>%1: %2 (statusword 0x%3)</source>
        <translation>%1: %2 (Statuswort 0x%3)</translation>
    </message>
    <message>
        <source>the drive went to fault</source>
        <translation>der Antrieb ist in Störung gegangen</translation>
    </message>
    <message>
        <source>no transition from this state</source>
        <translation>kein Übergang aus diesem Zustand</translation>
    </message>
    <message>
        <source>homing error</source>
        <translation>Referenzfahrtfehler</translation>
    </message>
    <message>
        <source>reading the state</source>
        <translation>Lesen des Zustands</translation>
    </message>
    <message>
        <source>switch on</source>
        <translation>Einschalten</translation>
    </message>
    <message>
        <source>enable operation</source>
        <translation>Betrieb freigeben</translation>
    </message>
    <message>
        <source>disable voltage</source>
        <translation>Spannung sperren</translation>
    </message>
    <message>
        <source>fault reset</source>
        <translation>Störungsquittierung</translation>
    </message>
    <message>
        <source>quick stop</source>
        <translation>Schnellhalt</translation>
    </message>
    <message>
        <source>quick stop active or switch on disabled</source>
        <translation>Schnellhalt aktiv oder Einschaltsperre</translation>
    </message>
    <message>
        <source>profile position</source>
        <translation>Profillage</translation>
    </message>
    <message>
        <source>profile velocity</source>
        <translation>Profilgeschwindigkeit</translation>
    </message>
    <message>
        <source>operation enabled</source>
        <translation>Betrieb freigegeben</translation>
    </message>
    <message>
        <source>homing attained (6041h bits 12 and 10)</source>
        <translation>Referenzfahrt abgeschlossen (6041h Bits 12 und 10)</translation>
    </message>
    <message>
        <source>profile torque</source>
        <translation>Profildrehmoment</translation>
    </message>
    <message>
        <source>a state from which %1 can be reached</source>
        <translation>ein Zustand, von dem aus %1 erreichbar ist</translation>
    </message>
    <message>
        <source>%1: no answer within %2 ms: the drive did not report its state (waiting for %3)</source>
        <translation>%1: keine Antwort innerhalb von %2 ms: der Antrieb meldete seinen Zustand nicht (beim Warten auf %3)</translation>
    </message>
    <message>
        <source>connection to %1 closed</source>
        <translation>Verbindung zu %1 geschlossen</translation>
    </message>
    <message>
        <source>the statusword was not read</source>
        <translation>das Statuswort wurde nicht gelesen</translation>
    </message>
</context>
<context>
    <name>db::cia402::Cia402StatusSource</name>
    <message>
        <source>Statusword:</source>
        <translation>Statuswort:</translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation>Ziel erreicht</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>In Bewegung</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Internal limit</source>
        <translation>Interne Begrenzung</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <source>Inputs (60FDh):</source>
        <translation>Eingänge (60FDh):</translation>
    </message>
    <message>
        <source>Outputs (60FEh.1):</source>
        <translation>Ausgänge (60FEh.1):</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Modus:</translation>
    </message>
    <message>
        <source>Position (6064h):</source>
        <translation>Position (6064h):</translation>
    </message>
    <message>
        <source>Velocity (606Ch):</source>
        <translation>Geschwindigkeit (606Ch):</translation>
    </message>
    <message>
        <source>Current (6078h):</source>
        <translation>Strom (6078h):</translation>
    </message>
    <message>
        <source>Last error (603Fh):</source>
        <translation>Letzter Fehler (603Fh):</translation>
    </message>
    <message>
        <source>No error</source>
        <translation>Kein Fehler</translation>
    </message>
    <message>
        <source>Status register (1002h):</source>
        <translation>Statusregister (1002h):</translation>
    </message>
    <message>
        <source>bit %1</source>
        <translation>Bit %1</translation>
    </message>
</context>
<context>
    <name>db::common</name>
    <message>
        <source>&apos;%1&apos; is not a node id 1..127</source>
        <translation>„%1“ ist keine Knoten-ID 1..127</translation>
    </message>
    <message>
        <source>no node ids given (e.g. 1,2,5)</source>
        <translation>keine Knoten-IDs angegeben (z. B. 1,2,5)</translation>
    </message>
</context>
<context>
    <name>db::core</name>
    <message>
        <source>&apos;%1&apos; is not a connection URI; write e.g. refgo://192.168.2.150 or canopen+slcan://HOST?node=50</source>
        <translation>„%1“ ist keine Verbindungs-URI; z. B. refgo://192.168.2.150 oder canopen+slcan://HOST?node=50 schreiben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid URI (%2)</source>
        <translation>„%1“ ist keine gültige URI (%2)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no valid host or interface</source>
        <translation>„%1“ hat keinen gültigen Host und keine gültige Schnittstelle</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: unexpected path &apos;%2&apos;</source>
        <translation>„%1“: unerwarteter Pfad „%2“</translation>
    </message>
    <message>
        <source>%1=%2 in %3: expected a number from %4 to %5</source>
        <translation>%1=%2 in %3: erwartet eine Zahl von %4 bis %5</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>%1 is not a drivebench device description</source>
        <translation>%1 ist keine drivebench-Gerätebeschreibung</translation>
    </message>
    <message>
        <source>%1: description version %2 is not supported (1 is)</source>
        <translation>%1: Beschreibungsversion %2 wird nicht unterstützt (nur 1)</translation>
    </message>
    <message>
        <source>%1: object #%2: %3</source>
        <translation>%1: Objekt #%2: %3</translation>
    </message>
    <message>
        <source>connection deleted</source>
        <translation>Verbindung gelöscht</translation>
    </message>
    <message>
        <source>no connection to %1 within %2 ms</source>
        <translation>keine Verbindung zu %1 innerhalb von %2 ms</translation>
    </message>
    <message>
        <source>cannot connect to %1</source>
        <translation>keine Verbindung zu %1 möglich</translation>
    </message>
    <message>
        <source>connection closed by the user</source>
        <translation>Verbindung vom Benutzer geschlossen</translation>
    </message>
    <message>
        <source>not connected to %1</source>
        <translation>nicht mit %1 verbunden</translation>
    </message>
    <message>
        <source>%1 %2 is write-only</source>
        <translation>%1 %2 ist nur schreibbar</translation>
    </message>
    <message>
        <source>%1 %2 is read-only</source>
        <translation>%1 %2 ist nur lesbar</translation>
    </message>
    <message>
        <source>connection to %1 closed</source>
        <translation>Verbindung zu %1 geschlossen</translation>
    </message>
    <message>
        <source>%1 cannot store parameters permanently</source>
        <translation>%1 kann Parameter nicht dauerhaft speichern</translation>
    </message>
    <message>
        <source>%1 cannot restore factory defaults</source>
        <translation>%1 kann die Werkseinstellungen nicht wiederherstellen</translation>
    </message>
    <message>
        <source>%1 takes no raw protocol commands</source>
        <translation>%1 nimmt keine rohen Protokollbefehle an</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 ist leer</translation>
    </message>
    <message>
        <source>%1 holds binary data, not a device description</source>
        <translation>%1 enthält Binärdaten, keine Gerätebeschreibung</translation>
    </message>
    <message>
        <source>%1 is not an EDS/DCF: no [sections] found</source>
        <translation>%1 ist keine EDS/DCF: keine [Abschnitte] gefunden</translation>
    </message>
    <message>
        <source>%1 is not an EDS/DCF: it has no object sections ([1000], [1018], ...)</source>
        <translation>%1 ist keine EDS/DCF: keine Objektabschnitte ([1000], [1018], ...)</translation>
    </message>
    <message>
        <source>%1: none of its object sections describes a usable object</source>
        <translation>%1: keiner der Objektabschnitte beschreibt ein brauchbares Objekt</translation>
    </message>
    <message>
        <source>%1 holds binary data, not an EDS/DCF</source>
        <translation>%1 enthält Binärdaten, keine EDS/DCF</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an object address; write INDEX:SUB in hex, e.g. 6041:0</source>
        <translation>„%1“ ist keine Objektadresse; INDEX:SUB hexadezimal schreiben, z. B. 6041:0</translation>
    </message>
    <message>
        <source>&apos;\%1&apos; needs %2 hex digits</source>
        <translation>„\%1“ braucht %2 Hex-Ziffern</translation>
    </message>
    <message>
        <source>unknown escape &apos;\%1&apos; in a quoted string</source>
        <translation>unbekannte Escape-Sequenz „\%1“ in einer Zeichenkette in Anführungszeichen</translation>
    </message>
    <message>
        <source>unterminated quoted string</source>
        <translation>nicht abgeschlossene Zeichenkette in Anführungszeichen</translation>
    </message>
    <message>
        <source>text right after a closing quote</source>
        <translation>Text direkt nach einem schließenden Anführungszeichen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>%1:%2: %3</source>
        <translation>%1:%2: %3</translation>
    </message>
    <message>
        <source>%1: empty file, not a drivebench parameter set</source>
        <translation>%1: leere Datei, kein drivebench-Parametersatz</translation>
    </message>
    <message>
        <source>unknown protocol &apos;%1&apos; in %2 (known: %3)</source>
        <translation>unbekanntes Protokoll „%1“ in %2 (bekannt: %3)</translation>
    </message>
    <message>
        <source>port %1 in %2 is out of range</source>
        <translation>Port %1 in %2 liegt außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>unknown protocol &apos;%1&apos; in %2</source>
        <translation>unbekanntes Protokoll „%1“ in %2</translation>
    </message>
    <message>
        <source>request still pending</source>
        <translation>Anfrage noch offen</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>request was deleted</source>
        <translation>Anfrage wurde gelöscht</translation>
    </message>
    <message>
        <source>no answer within %1 ms</source>
        <translation>keine Antwort innerhalb von %1 ms</translation>
    </message>
    <message>
        <source>%1 does not fit %2 (%3 .. %4)</source>
        <translation>%1 passt nicht in %2 (%3 .. %4)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid %2 value</source>
        <translation>„%1“ ist kein gültiger %2-Wert</translation>
    </message>
    <message>
        <source>no value</source>
        <translation>kein Wert</translation>
    </message>
    <message>
        <source>VISIBLE_STRING allows printable ASCII only; &apos;%1&apos; is not</source>
        <translation>VISIBLE_STRING erlaubt nur druckbares ASCII; „%1“ ist es nicht</translation>
    </message>
    <message>
        <source>%1 needs bytes</source>
        <translation>%1 braucht Bytes</translation>
    </message>
    <message>
        <source>%1 needs %2 bytes, got %3</source>
        <translation>%1 braucht %2 Bytes, erhalten %3</translation>
    </message>
    <message>
        <source>BOOLEAN byte is 0x%1, not 0 or 1</source>
        <translation>BOOLEAN-Byte ist 0x%1, nicht 0 oder 1</translation>
    </message>
    <message>
        <source>UNICODE_STRING has an odd number of bytes (%1)</source>
        <translation>UNICODE_STRING hat eine ungerade Anzahl Bytes (%1)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a list of hex bytes (e.g. 01 02 FF)</source>
        <translation>„%1“ ist keine Liste von Hex-Bytes (z. B. 01 02 FF)</translation>
    </message>
    <message>
        <source>%1 is outside the object&apos;s range %2 .. %3</source>
        <translation>%1 liegt außerhalb des Wertebereichs des Objekts %2 .. %3</translation>
    </message>
    <message>
        <source>scaling factor is 0</source>
        <translation>Skalierungsfaktor ist 0</translation>
    </message>
    <message>
        <source>value is not finite</source>
        <translation>Wert ist nicht endlich</translation>
    </message>
    <message>
        <source>%1 has no physical value</source>
        <translation>%1 hat keinen physikalischen Wert</translation>
    </message>
    <message>
        <source>%1 is XML but not an XDD/XDC: the root element is &lt;%2&gt;, not &lt;ISO15745ProfileContainer&gt;</source>
        <translation>%1 ist XML, aber keine XDD/XDC: das Wurzelelement ist &lt;%2&gt;, nicht &lt;ISO15745ProfileContainer&gt;</translation>
    </message>
    <message>
        <source>%1: XML error at line %2, column %3: %4</source>
        <translation>%1: XML-Fehler in Zeile %2, Spalte %3: %4</translation>
    </message>
    <message>
        <source>%1: no CANopenObjectList; not a CANopen XDD/XDC</source>
        <translation>%1: keine CANopenObjectList; keine CANopen-XDD/XDC</translation>
    </message>
    <message>
        <source>%1: the CANopenObjectList holds no usable object</source>
        <translation>%1: die CANopenObjectList enthält kein brauchbares Objekt</translation>
    </message>
    <message>
        <source>%1 holds binary data, not an XDD/XDC</source>
        <translation>%1 enthält Binärdaten, keine XDD/XDC</translation>
    </message>
    <message>
        <source>bad index</source>
        <translation>ungültiger Index</translation>
    </message>
    <message>
        <source>bad sub-index</source>
        <translation>ungültiger Subindex</translation>
    </message>
    <message>
        <source>unknown type &apos;%1&apos;</source>
        <translation>unbekannter Typ „%1“</translation>
    </message>
    <message>
        <source>unknown access &apos;%1&apos;</source>
        <translation>unbekannter Zugriff „%1“</translation>
    </message>
    <message>
        <source>cannot evaluate &apos;%1&apos;</source>
        <translation>„%1“ kann nicht ausgewertet werden</translation>
    </message>
    <message>
        <source>&apos;%1&apos; with node id %2: %3</source>
        <translation>„%1“ mit Knoten-ID %2: %3</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>broken section header &apos;%1&apos;; skipped</source>
        <translation>fehlerhafter Abschnittskopf „%1“; übersprungen</translation>
    </message>
    <message>
        <source>section [%1] appears again; merged</source>
        <translation>Abschnitt [%1] kommt erneut vor; zusammengeführt</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a key=value line in a section; ignored</source>
        <translation>„%1“ ist keine Schlüssel=Wert-Zeile in einem Abschnitt; ignoriert</translation>
    </message>
    <message>
        <source>[%1] %2 given twice; the last one is used</source>
        <translation>[%1] %2 doppelt angegeben; die letzte Angabe gilt</translation>
    </message>
    <message>
        <source>entry %1=%2 is not an index</source>
        <translation>Eintrag %1=%2 ist kein Index</translation>
    </message>
    <message>
        <source>lists %1 but there is no [%2] section</source>
        <translation>listet %1, aber es gibt keinen Abschnitt [%2]</translation>
    </message>
    <message>
        <source>SupportedObjects=%1 but %2 entries are listed</source>
        <translation>SupportedObjects=%1, aber %2 Einträge sind aufgeführt</translation>
    </message>
    <message>
        <source>object lists</source>
        <translation>Objektlisten</translation>
    </message>
    <message>
        <source>ObjectType &apos;%1&apos; is not a number; object skipped</source>
        <translation>ObjectType „%1“ ist keine Zahl; Objekt übersprungen</translation>
    </message>
    <message>
        <source>NULL object skipped</source>
        <translation>NULL-Objekt übersprungen</translation>
    </message>
    <message>
        <source>a VAR/DOMAIN with sub-index sections; those are ignored</source>
        <translation>ein VAR/DOMAIN mit Subindex-Abschnitten; diese werden ignoriert</translation>
    </message>
    <message>
        <source>unknown ObjectType %1; read as %2</source>
        <translation>unbekannter ObjectType %1; gelesen als %2</translation>
    </message>
    <message>
        <source>ARRAY/RECORD without sub-index sections; skipped</source>
        <translation>ARRAY/RECORD ohne Subindex-Abschnitte; übersprungen</translation>
    </message>
    <message>
        <source>SubNumber=%1 but %2 sub-index sections are present</source>
        <translation>SubNumber=%1, aber %2 Subindex-Abschnitte sind vorhanden</translation>
    </message>
    <message>
        <source>no sub-index 0; made one (UNSIGNED8, ro, %1)</source>
        <translation>kein Subindex 0; einer wurde angelegt (UNSIGNED8, ro, %1)</translation>
    </message>
    <message>
        <source>sub-index 0 should be UNSIGNED8 (number of entries), is %1</source>
        <translation>Subindex 0 sollte UNSIGNED8 sein (Anzahl Einträge), ist %1</translation>
    </message>
    <message>
        <source>default %1 is below the highest sub-index present (%2)</source>
        <translation>Standardwert %1 liegt unter dem höchsten vorhandenen Subindex (%2)</translation>
    </message>
    <message>
        <source>no ParameterName; called &apos;%1&apos;</source>
        <translation>kein ParameterName; benannt „%1“</translation>
    </message>
    <message>
        <source>no DataType; read as DOMAIN</source>
        <translation>kein DataType; gelesen als DOMAIN</translation>
    </message>
    <message>
        <source>DataType %1 is not a basic type; read as DOMAIN</source>
        <translation>DataType %1 ist kein Basistyp; gelesen als DOMAIN</translation>
    </message>
    <message>
        <source>PDOMapping &apos;%1&apos; is not 0/1</source>
        <translation>PDOMapping „%1“ ist nicht 0/1</translation>
    </message>
    <message>
        <source>ObjFlags &apos;%1&apos; is not a number</source>
        <translation>ObjFlags „%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>Factor &apos;%1&apos; is not a number</source>
        <translation>Factor „%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>LowLimit %1 is above HighLimit %2</source>
        <translation>LowLimit %1 liegt über HighLimit %2</translation>
    </message>
    <message>
        <source>%1 ignored: %2</source>
        <translation>%1 ignoriert: %2</translation>
    </message>
    <message>
        <source>%1 &apos;%2&apos; needs a node id; ignored</source>
        <translation>%1 „%2“ braucht eine Knoten-ID; ignoriert</translation>
    </message>
    <message>
        <source>not a drivebench parameter set (expected &apos;%1&apos; as the first line)</source>
        <translation>kein drivebench-Parametersatz (erwartet „%1“ als erste Zeile)</translation>
    </message>
    <message>
        <source>the line is not valid UTF-8</source>
        <translation>die Zeile ist kein gültiges UTF-8</translation>
    </message>
    <message>
        <source>expected &apos;format %1&apos;</source>
        <translation>erwartet „format %1“</translation>
    </message>
    <message>
        <source>bad format version &apos;%1&apos;</source>
        <translation>ungültige Formatversion „%1“</translation>
    </message>
    <message>
        <source>format %1 is newer than this drivebench reads (%2)</source>
        <translation>Format %1 ist neuer, als dieses drivebench lesen kann (%2)</translation>
    </message>
    <message>
        <source>expected &apos;end&apos; after %1 objects</source>
        <translation>erwartet „end“ nach %1 Objekten</translation>
    </message>
    <message>
        <source>text after &apos;end&apos;</source>
        <translation>Text nach „end“</translation>
    </message>
    <message>
        <source>truncated: no &apos;format&apos; line</source>
        <translation>abgeschnitten: keine „format“-Zeile</translation>
    </message>
    <message>
        <source>truncated: no &apos;entries&apos; line</source>
        <translation>abgeschnitten: keine „entries“-Zeile</translation>
    </message>
    <message>
        <source>truncated: &apos;entries %1&apos; but only %2 object lines</source>
        <translation>abgeschnitten: „entries %1“, aber nur %2 Objektzeilen</translation>
    </message>
    <message>
        <source>truncated: no &apos;end&apos; line</source>
        <translation>abgeschnitten: keine „end“-Zeile</translation>
    </message>
    <message>
        <source>&apos;%1&apos; takes %2 values</source>
        <translation>„%1“ erwartet %2 Werte</translation>
    </message>
    <message>
        <source>bad time &apos;%1&apos;</source>
        <translation>ungültige Zeit „%1“</translation>
    </message>
    <message>
        <source>bad object count &apos;%1&apos;</source>
        <translation>ungültige Objektanzahl „%1“</translation>
    </message>
    <message>
        <source>unknown header line &apos;%1&apos;</source>
        <translation>unbekannte Kopfzeile „%1“</translation>
    </message>
    <message>
        <source>expected an object line: ADDRESS &quot;NAME&quot; TYPE VALUE &quot;UNIT&quot; (%1 of %2 objects read)</source>
        <translation>erwartet eine Objektzeile: ADRESSE &quot;NAME&quot; TYP WERT &quot;EINHEIT&quot; (%1 von %2 Objekten gelesen)</translation>
    </message>
    <message>
        <source>%1 appears twice</source>
        <translation>%1 kommt doppelt vor</translation>
    </message>
    <message>
        <source>index &apos;%1&apos; is not a hex index; skipped</source>
        <translation>Index „%1“ ist kein Hex-Index; übersprungen</translation>
    </message>
    <message>
        <source>no objectType; read as %1</source>
        <translation>kein objectType; gelesen als %1</translation>
    </message>
    <message>
        <source>ARRAY/RECORD without CANopenSubObjects; skipped</source>
        <translation>ARRAY/RECORD ohne CANopenSubObjects; übersprungen</translation>
    </message>
    <message>
        <source>VAR with CANopenSubObjects; those are ignored</source>
        <translation>VAR mit CANopenSubObjects; diese werden ignoriert</translation>
    </message>
    <message>
        <source>subNumber=%1 but %2 CANopenSubObjects are present</source>
        <translation>subNumber=%1, aber %2 CANopenSubObjects sind vorhanden</translation>
    </message>
    <message>
        <source>subIndex &apos;%1&apos; is not hex; skipped</source>
        <translation>subIndex „%1“ ist nicht hexadezimal; übersprungen</translation>
    </message>
    <message>
        <source>no sub-index 0 (number of entries)</source>
        <translation>kein Subindex 0 (Anzahl Einträge)</translation>
    </message>
    <message>
        <source>uniqueIDRef &apos;%1&apos; names no parameter</source>
        <translation>uniqueIDRef „%1“ nennt keinen Parameter</translation>
    </message>
    <message>
        <source>no name; called &apos;%1&apos;</source>
        <translation>kein Name; benannt „%1“</translation>
    </message>
    <message>
        <source>%1: unknown &quot;addresses&quot; &apos;%2&apos; (canopen or parameter)</source>
        <translation>%1: unbekannte „addresses“ „%2“ (canopen oder parameter)</translation>
    </message>
    <message>
        <source>decimals %1 (0-9 allowed)</source>
        <translation>Dezimalstellen %1 (0-9 erlaubt)</translation>
    </message>
    <message>
        <source>unknown address format &apos;%1&apos; (canopen or parameter)</source>
        <translation>unbekanntes Adressformat „%1“ (canopen oder parameter)</translation>
    </message>
    <message>
        <source>bad address &apos;%1&apos; (%2 addresses are written like %3)</source>
        <translation>ungültige Adresse „%1“ (%2-Adressen schreibt man wie %3)</translation>
    </message>
    <message>
        <source>a device description</source>
        <translation>eine Gerätebeschreibung</translation>
    </message>
    <message>
        <source>%1: JSON error at %2: %3</source>
        <translation>%1: JSON-Fehler in %2: %3</translation>
    </message>
    <message>
        <source>a parameter set</source>
        <translation>ein Parametersatz</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is not a language code such as &quot;de&quot;</source>
        <translation>„%1“: „%2“ ist kein Sprachcode wie „de“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a non-empty text</source>
        <translation>„%1“ muss ein nicht leerer Text sein</translation>
    </message>
    <message>
        <source>%1: error #%2: %3</source>
        <translation>%1: Fehler #%2: %3</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must map values to texts</source>
        <translation>„%1“ muss Werten Texte zuordnen</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is not a value of &quot;enum&quot;</source>
        <translation>„%1“: %2 ist kein Wert von „enum“</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the text of %2 must be a non-empty text</source>
        <translation>„%1“: der Text von %2 muss ein nicht leerer Text sein</translation>
    </message>
    <message>
        <source>bit #%1: %2</source>
        <translation>Bit #%1: %2</translation>
    </message>
    <message>
        <source>index</source>
        <translation>Index</translation>
    </message>
    <message>
        <source>sub-index</source>
        <translation>Subindex</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>data set</source>
        <translation>Datensatz</translation>
    </message>
</context>
<context>
    <name>db::description</name>
    <message>
        <source>vendor %1, product %2</source>
        <translation>Hersteller %1, Produkt %2</translation>
    </message>
    <message>
        <source>, revision %1</source>
        <translation>, Revision %1</translation>
    </message>
    <message>
        <source>%1 states no vendor id: it cannot be matched to a device</source>
        <translation>%1 nennt keine Herstellerkennung: sie kann keinem Gerät zugeordnet werden</translation>
    </message>
    <message>
        <source>no description folder is set to add %1 to</source>
        <translation>es ist kein Beschreibungsordner eingestellt, in den %1 kommen könnte</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>der Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>db::files</name>
    <message>
        <source>cannot read %1: it is a folder, not a file</source>
        <translation>%1 kann nicht gelesen werden: Es ist ein Ordner, keine Datei</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>%1 is %2 MB, more than the %3 MB %4 may have: is it the right file?</source>
        <translation>%1 ist %2 MB groß, mehr als die %3 MB, die %4 haben darf: Ist es die richtige Datei?</translation>
    </message>
    <message>
        <source>%1 is more than the %2 MB %3 may have: is it the right file?</source>
        <translation>%1 ist größer als die %2 MB, die %3 haben darf: Ist es die richtige Datei?</translation>
    </message>
    <message>
        <source>line %1, column %2</source>
        <translation>Zeile %1, Spalte %2</translation>
    </message>
</context>
<context>
    <name>db::gui::MainWindow</name>
    <message>
        <source>drivebench</source>
        <translation>drivebench</translation>
    </message>
    <message>
        <source>Drive Status</source>
        <translation>Antriebsstatus</translation>
    </message>
    <message>
        <source>Scope</source>
        <translation>Oszilloskop</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <source>Object Access</source>
        <translation>Objektzugriff</translation>
    </message>
    <message>
        <source>CANopen Nodes</source>
        <translation>CANopen-Knoten</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>CAN Monitor</source>
        <translation>CAN-Monitor</translation>
    </message>
    <message>
        <source>Morse IP</source>
        <translation>Morse-IP</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation>&amp;Verbinden…</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About drivebench</source>
        <translation>&amp;Über drivebench</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Cannot connect to %1: %2</source>
        <translation>Verbindung zu %1 nicht möglich: %2</translation>
    </message>
    <message>
        <source>Connecting to %1</source>
        <translation>Verbinde mit %1</translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <translation>%1 ist %2</translation>
    </message>
    <message>
        <source>Removed %1</source>
        <translation>%1 entfernt</translation>
    </message>
    <message>
        <source>About drivebench</source>
        <translation>Über drivebench</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>No device</source>
        <translation>Kein Gerät</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <source>Motion stopped: %1</source>
        <translation>Bewegung gestoppt: %1</translation>
    </message>
    <message>
        <source>connection closed by the user</source>
        <translation>Verbindung vom Benutzer geschlossen</translation>
    </message>
    <message>
        <source>Object Dictionary</source>
        <translation>Objektverzeichnis</translation>
    </message>
    <message>
        <source>Parameter Sets</source>
        <translation>Parametersätze</translation>
    </message>
    <message>
        <source>Parameter set</source>
        <translation>Parametersatz</translation>
    </message>
    <message>
        <source>&amp;Parameters</source>
        <translation>&amp;Parameter</translation>
    </message>
    <message>
        <source>%1 (%2)[*]</source>
        <translation>%1 (%2)[*]</translation>
    </message>
    <message>
        <source>&amp;Refresh Objects</source>
        <translation>Objekte &amp;aktualisieren</translation>
    </message>
    <message>
        <source>&amp;Filter Objects</source>
        <translation>Objekte &amp;filtern</translation>
    </message>
    <message>
        <source>&amp;User Manual</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>User Manual</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <source>The manual is missing from this build.</source>
        <translation>Das Handbuch fehlt in dieser Version.</translation>
    </message>
    <message>
        <source>NM17x Line</source>
        <translation>NM17x-Linie</translation>
    </message>
    <message>
        <source>&amp;Settings…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>Reset &amp;Layout</source>
        <translation>&amp;Layout zurücksetzen</translation>
    </message>
    <message>
        <source>%1 is already in the device list; it was not connected a second time</source>
        <translation>%1 ist bereits in der Geräteliste; es wurde kein zweites Mal verbunden</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: the link is up, waiting for the device to answer.</source>
        <translation>%1: die Verbindung steht, warte auf Antwort des Geräts.</translation>
    </message>
    <message>
        <source>%1: %2.</source>
        <translation>%1: %2.</translation>
    </message>
    <message>
        <source>The values shown are from %1 and may be out of date.</source>
        <translation>Die angezeigten Werte stammen von %1 und sind möglicherweise veraltet.</translation>
    </message>
    <message>
        <source>%1: disconnected by you.</source>
        <translation>%1: von Ihnen getrennt.</translation>
    </message>
    <message>
        <source>The drive at %1 is enabled. Closing the connection leaves it enabled (it stops by its own supervision only if that is set up). Close the connection anyway?</source>
        <translation>Der Antrieb unter %1 ist freigegeben. Das Schließen der Verbindung lässt ihn freigegeben (er hält nur durch seine eigene Überwachung an, wenn diese eingerichtet ist). Verbindung trotzdem schließen?</translation>
    </message>
    <message>
        <source>Drive enabled</source>
        <translation>Antrieb freigegeben</translation>
    </message>
    <message>
        <source>&lt;h3&gt;drivebench %1&lt;/h3&gt;&lt;p&gt;Commissioning tool for industrial drives.&lt;/p&gt;&lt;p&gt;Built from commit %2 with Qt %3 (running on Qt %4) and QCustomPlot.&lt;/p&gt;&lt;p&gt;Copyright 2026 The drivebench developers. drivebench has not been released under a public licence: all rights are reserved by its developers; ask them before you copy or redistribute it.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;drivebench %1&lt;/h3&gt;&lt;p&gt;Inbetriebnahme-Werkzeug für industrielle Antriebe.&lt;/p&gt;&lt;p&gt;Gebaut aus Commit %2 mit Qt %3 (läuft mit Qt %4) und QCustomPlot.&lt;/p&gt;&lt;p&gt;Copyright 2026 Die drivebench-Entwickler. drivebench wurde nicht unter einer öffentlichen Lizenz veröffentlicht: alle Rechte liegen bei seinen Entwicklern; fragen Sie sie, bevor Sie es kopieren oder weitergeben.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>Enable</source>
        <translation>Freigeben</translation>
    </message>
    <message>
        <source>Switch the current drive&apos;s power stage on (as in the Motion dock)</source>
        <translation>Die Endstufe des aktuellen Antriebs einschalten (wie im Bewegungs-Dock)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Stop in the toolbar</source>
        <translation>Stopp in der Werkzeugleiste</translation>
    </message>
    <message>
        <source>Quick stop of any motion (Esc)</source>
        <translation>Schnellhalt jeder Bewegung (Esc)</translation>
    </message>
    <message>
        <source>Start Scope</source>
        <translation>Oszilloskop starten</translation>
    </message>
    <message>
        <source>Start or stop the scope&apos;s recording (Space or F5 on the Scope page)</source>
        <translation>Aufzeichnung des Oszilloskops starten oder stoppen (Leertaste oder F5 auf der Seite Oszilloskop)</translation>
    </message>
    <message>
        <source>Stop Scope</source>
        <translation>Oszilloskop stoppen</translation>
    </message>
    <message>
        <source>No device connected</source>
        <translation>Kein Gerät verbunden</translation>
    </message>
    <message>
        <source>Connect to a drive over RefGo, VABus or CANopen, or try drivebench on a simulated drive.</source>
        <translation>Verbinden Sie sich über RefGo, VABus oder CANopen mit einem Antrieb, oder probieren Sie drivebench an einem simulierten Antrieb aus.</translation>
    </message>
    <message>
        <source>Connect…</source>
        <translation>Verbinden…</translation>
    </message>
    <message>
        <source>Start the Demo</source>
        <translation>Demo starten</translation>
    </message>
    <message>
        <source>A simulated MovingCap drive in this program, connected over RefGo and CANopen</source>
        <translation>Ein simulierter MovingCap-Antrieb in diesem Programm, verbunden über RefGo und CANopen</translation>
    </message>
    <message>
        <source>Recent connections:</source>
        <translation>Letzte Verbindungen:</translation>
    </message>
    <message>
        <source>Connect to %1</source>
        <translation>Mit %1 verbinden</translation>
    </message>
    <message>
        <source>%1: connection lost; reconnecting automatically, attempt %2.</source>
        <translation>%1: Verbindung verloren; automatischer Wiederaufbau, Versuch %2.</translation>
    </message>
    <message>
        <source>Reconnecting automatically.</source>
        <translation>Die Verbindung wird automatisch wieder aufgebaut.</translation>
    </message>
    <message numerus="yes">
        <source>Automatic reconnect gave up after %n attempt(s).</source>
        <translation>
            <numerusform>Automatischer Wiederaufbau nach %n Versuch aufgegeben.</numerusform>
            <numerusform>Automatischer Wiederaufbau nach %n Versuchen aufgegeben.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: reconnecting automatically, attempt %2</source>
        <translation>%1: automatischer Wiederaufbau, Versuch %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: the link is up again after %n attempt(s)</source>
        <translation>
            <numerusform>%1: Verbindung nach %n Versuch wieder aufgebaut</numerusform>
            <numerusform>%1: Verbindung nach %n Versuchen wieder aufgebaut</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: automatic reconnect gave up after %n attempt(s) in %2 s</source>
        <translation>
            <numerusform>%1: automatischer Wiederaufbau nach %n Versuch in %2 s aufgegeben</numerusform>
            <numerusform>%1: automatischer Wiederaufbau nach %n Versuchen in %2 s aufgegeben</numerusform>
        </translation>
    </message>
    <message>
        <source>Changes</source>
        <translation>Änderungen</translation>
    </message>
    <message>
        <source>all parameters</source>
        <translation>alle Parameter</translation>
    </message>
    <message>
        <source>CANopen Network</source>
        <translation>CANopen-Netz</translation>
    </message>
    <message>
        <source>Description &amp;Library…</source>
        <translation>Beschreibungsbib&amp;liothek…</translation>
    </message>
    <message>
        <source>%1 added to the description library</source>
        <translation>%1 zur Beschreibungsbibliothek hinzugefügt</translation>
    </message>
</context>
<context>
    <name>db::gui::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>As the system</source>
        <translation>Wie das System</translation>
    </message>
    <message>
        <source>Takes effect at the next start.</source>
        <translation>Wirkt ab dem nächsten Start.</translation>
    </message>
    <message>
        <source>How long a new connection may take to reach the device</source>
        <translation>Wie lange eine neue Verbindung brauchen darf, um das Gerät zu erreichen</translation>
    </message>
    <message>
        <source>How long a read or write waits for the device&apos;s answer</source>
        <translation>Wie lange ein Lesen oder Schreiben auf die Antwort des Geräts wartet</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Clear All</source>
        <translation>Alle löschen</translation>
    </message>
    <message>
        <source>Language:</source>
        <translation>Sprache:</translation>
    </message>
    <message>
        <source>Connect time limit:</source>
        <translation>Zeitlimit Verbindungsaufbau:</translation>
    </message>
    <message>
        <source>Answer time limit:</source>
        <translation>Zeitlimit Antwort:</translation>
    </message>
    <message>
        <source>Recent connections</source>
        <translation>Letzte Verbindungen</translation>
    </message>
    <message>
        <source>Reconnect automatically after a lost connection</source>
        <translation>Verlorene Verbindung automatisch wieder aufbauen</translation>
    </message>
    <message>
        <source>When a link that was up goes down (not when you disconnect), it is opened again every few seconds until the device is back or the time below has passed. Each attempt is shown in the log.</source>
        <translation>Bricht eine bestehende Verbindung ab (nicht wenn Sie sie trennen), wird sie alle paar Sekunden neu geöffnet, bis das Gerät wieder antwortet oder die unten eingestellte Zeit vergangen ist. Jeder Versuch erscheint im Protokoll.</translation>
    </message>
    <message>
        <source>Keep trying for:</source>
        <translation>Wie lange versuchen:</translation>
    </message>
</context>
<context>
    <name>db::morse</name>
    <message>
        <source>%1:%2: %3</source>
        <translation>%1:%2: %3</translation>
    </message>
    <message>
        <source>%1: no samples</source>
        <translation>%1: keine Messwerte</translation>
    </message>
    <message>
        <source>region outside the %1x%2 frame</source>
        <translation>Bereich außerhalb des Bilds %1x%2</translation>
    </message>
    <message>
        <source>video writer: %1</source>
        <translation>Videoschreiber: %1</translation>
    </message>
    <message>
        <source>IP address decoded</source>
        <translation>IP-Adresse dekodiert</translation>
    </message>
    <message>
        <source>no usable samples (empty, not finite or time not increasing)</source>
        <translation>keine brauchbaren Messwerte (leer, nicht endlich oder Zeit nicht steigend)</translation>
    </message>
    <message>
        <source>no modulation: the brightness never shows two distinct levels (LED not in view, covered or not blinking)</source>
        <translation>keine Modulation: die Helligkeit zeigt nie zwei unterscheidbare Stufen (LED nicht im Bild, verdeckt oder blinkt nicht)</translation>
    </message>
    <message>
        <source>the LED blinks, but not with Morse timing of 40-500 ms per unit</source>
        <translation>die LED blinkt, aber nicht im Morsetakt von 40-500 ms je Einheit</translation>
    </message>
    <message>
        <source>recording too short: not one complete message yet</source>
        <translation>Aufnahme zu kurz: noch keine vollständige Nachricht</translation>
    </message>
    <message>
        <source>Morse text without a valid &quot;MC+IPa+b+c+d:&quot; message</source>
        <translation>Morsetext ohne gültige Nachricht „MC+IPa+b+c+d:“</translation>
    </message>
    <message>
        <source>IP address seen, but the repetitions do not agree enough yet</source>
        <translation>IP-Adresse erkannt, aber die Wiederholungen stimmen noch nicht genug überein</translation>
    </message>
    <message>
        <source>a %1 s gap in time after sample %2 (at %3 s)</source>
        <translation>eine Zeitlücke von %1 s nach Messwert %2 (bei %3 s)</translation>
    </message>
    <message>
        <source>%1 more</source>
        <translation>%1 weitere</translation>
    </message>
    <message>
        <source>the recording has %1: read as %2 recordings</source>
        <translation>die Aufnahme hat %1: als %2 Aufnahmen gelesen</translation>
    </message>
    <message>
        <source>; octets read so far: %1</source>
        <translation>; bisher gelesene Oktette: %1</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>line longer than %1 characters</source>
        <translation>Zeile länger als %1 Zeichen</translation>
    </message>
    <message>
        <source>time %1 s is negative</source>
        <translation>Zeit %1 s ist negativ</translation>
    </message>
    <message>
        <source>time %1 s repeats the previous row&apos;s time</source>
        <translation>Zeit %1 s wiederholt die Zeit der vorigen Zeile</translation>
    </message>
    <message>
        <source>time %1 s is before the previous row&apos;s %2 s (rows must be in time order)</source>
        <translation>Zeit %1 s liegt vor %2 s der vorigen Zeile (Zeilen müssen zeitlich geordnet sein)</translation>
    </message>
    <message>
        <source>more than %1 samples: cut the recording</source>
        <translation>mehr als %1 Messwerte: Aufnahme kürzen</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1: Datei nicht vorhanden</translation>
    </message>
    <message>
        <source>%1: not a readable video (%2)</source>
        <translation>%1: kein lesbares Video (%2)</translation>
    </message>
    <message>
        <source>%1: no stream information</source>
        <translation>%1: keine Stream-Informationen</translation>
    </message>
    <message>
        <source>%1: no decodable video stream</source>
        <translation>%1: kein dekodierbarer Videostream</translation>
    </message>
    <message>
        <source>%1: cannot open the %2 decoder</source>
        <translation>%1: der Decoder %2 kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>%1: video without a frame size</source>
        <translation>%1: Video ohne Bildgröße</translation>
    </message>
    <message>
        <source>%1: longer than %2 frames of %3x%4 pixels (%5 MB) at once: cut the video</source>
        <translation>%1: länger als %2 Bilder mit %3x%4 Pixeln (%5 MB) auf einmal: Video kürzen</translation>
    </message>
    <message>
        <source>%1: no frames decoded</source>
        <translation>%1: keine Bilder dekodiert</translation>
    </message>
</context>
<context>
    <name>db::morseio::CameraSource</name>
    <message>
        <source>Camera &quot;%1&quot; delivers no frames after %2 s (in use by another program, or no permission for its device?)</source>
        <translation>Kamera „%1“ liefert nach %2 s keine Bilder (von einem anderen Programm belegt oder keine Berechtigung für das Gerät?)</translation>
    </message>
    <message>
        <source>No camera found (Qt Multimedia lists none)</source>
        <translation>Keine Kamera gefunden (Qt Multimedia listet keine)</translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot;: %2</source>
        <translation>Kamera „%1“: %2</translation>
    </message>
    <message>
        <source>cannot be opened (busy or no permission?)</source>
        <translation>kann nicht geöffnet werden (belegt oder keine Berechtigung?)</translation>
    </message>
    <message>
        <source>Starting camera &quot;%1&quot;…</source>
        <translation>Starte Kamera „%1“…</translation>
    </message>
    <message>
        <source>Region %1,%2 %3x%4 lies outside the %5x%6 camera frame; searching for the blinking LED automatically</source>
        <translation>Bereich %1,%2 %3x%4 liegt außerhalb des Kamerabilds %5x%6; suche die blinkende LED automatisch</translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot; was disconnected</source>
        <translation>Kamera „%1“ wurde getrennt</translation>
    </message>
    <message>
        <source>Camera frames cannot be read (pixel format %1, %2x%3)</source>
        <translation>Kamerabilder können nicht gelesen werden (Pixelformat %1, %2x%3)</translation>
    </message>
    <message>
        <source>Searching for the blinking LED…</source>
        <translation>Suche die blinkende LED…</translation>
    </message>
    <message>
        <source>LED at %1,%2 (%3x%4 px)%5</source>
        <translation>LED bei %1,%2 (%3x%4 px)%5</translation>
    </message>
    <message>
        <source>, your region</source>
        <translation>, Ihr Bereich</translation>
    </message>
    <message>
        <source>LED lost (no blinking for %1 s): searching again…</source>
        <translation>LED verloren (seit %1 s kein Blinken): suche erneut…</translation>
    </message>
</context>
<context>
    <name>db::motion</name>
    <message>
        <source>connection to %1 closed</source>
        <translation>Verbindung zu %1 geschlossen</translation>
    </message>
    <message>
        <source>power changed</source>
        <translation>Leistungszustand geändert</translation>
    </message>
    <message>
        <source>the drive has no homing mode</source>
        <translation>der Antrieb hat keinen Referenzfahrtmodus</translation>
    </message>
    <message>
        <source>the drive has no profile torque mode</source>
        <translation>der Antrieb hat keinen Profil-Drehmomentmodus</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>gestoppt</translation>
    </message>
    <message>
        <source>deadman watchdog: no keep-alive for %1 ms, axis stopped</source>
        <translation>Totmann-Überwachung: seit %1 ms kein Lebenszeichen, Achse gestoppt</translation>
    </message>
    <message>
        <source>stopped (stop now)</source>
        <translation>gestoppt (sofort stoppen)</translation>
    </message>
    <message>
        <source>aborted by %1</source>
        <translation>abgebrochen durch %1</translation>
    </message>
    <message>
        <source>connection lost</source>
        <translation>Verbindung verloren</translation>
    </message>
    <message>
        <source>velocity override</source>
        <translation>Geschwindigkeits-Override</translation>
    </message>
    <message>
        <source>power switched off</source>
        <translation>Leistung abgeschaltet</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 abgelehnt: %2</translation>
    </message>
    <message>
        <source>target outside the software limit switches</source>
        <translation>Ziel außerhalb der Software-Endschalter</translation>
    </message>
    <message>
        <source>travel direction not permitted</source>
        <translation>Fahrtrichtung nicht erlaubt</translation>
    </message>
    <message>
        <source>target outside the cycle length</source>
        <translation>Ziel außerhalb der Zykluslänge</translation>
    </message>
    <message>
        <source>hardware limit switch active in the travel direction</source>
        <translation>Hardware-Endschalter in Fahrtrichtung aktiv</translation>
    </message>
    <message>
        <source>velocity, acceleration, deceleration or jerk is zero</source>
        <translation>Geschwindigkeit, Beschleunigung, Verzögerung oder Ruck ist null</translation>
    </message>
    <message>
        <source>maximum acceleration or maximum jerk of the axis is zero</source>
        <translation>maximale Beschleunigung oder maximaler Ruck der Achse ist null</translation>
    </message>
    <message>
        <source>axis not at standstill</source>
        <translation>Achse nicht im Stillstand</translation>
    </message>
    <message>
        <source>homing method inactive</source>
        <translation>Referenzfahrtmethode inaktiv</translation>
    </message>
    <message>
        <source>MC_Stop is active</source>
        <translation>MC_Stop ist aktiv</translation>
    </message>
    <message>
        <source>axis not enabled or in ErrorStop</source>
        <translation>Achse nicht freigegeben oder in ErrorStop</translation>
    </message>
    <message>
        <source>this drive has no table of motion blocks</source>
        <translation>dieser Antrieb hat keine Fahrsatztabelle</translation>
    </message>
    <message>
        <source>drive fault (statusword 0x%1)</source>
        <translation>Antriebsstörung (Statuswort 0x%1)</translation>
    </message>
    <message>
        <source>power stage switched off</source>
        <translation>Leistungsteil abgeschaltet</translation>
    </message>
    <message>
        <source>mode change while moving</source>
        <translation>Betriebsartwechsel während der Bewegung</translation>
    </message>
    <message>
        <source>%1: the drive stopped at %2, short of the target %3 (halted by another program or the drive itself)</source>
        <translation>%1: Der Antrieb hat bei %2 angehalten, vor dem Ziel %3 (angehalten von einem anderen Programm oder vom Antrieb selbst)</translation>
    </message>
    <message>
        <source>Motion block</source>
        <translation>Fahrsatz</translation>
    </message>
    <message>
        <source>this drive has no electronic gear</source>
        <translation>dieser Antrieb hat kein elektronisches Getriebe</translation>
    </message>
    <message>
        <source>the drive has no electronic gear</source>
        <translation>der Antrieb hat kein elektronisches Getriebe</translation>
    </message>
    <message>
        <source>gear ratio needs a numerator other than 0 and a denominator of at least 1</source>
        <translation>die Getriebeübersetzung braucht einen Zähler ungleich 0 und einen Nenner von mindestens 1</translation>
    </message>
</context>
<context>
    <name>db::nm17x::BroadcastAddressing</name>
    <message>
        <source>broadcast addressing is already running</source>
        <translation>Broadcast-Adressierung läuft bereits</translation>
    </message>
    <message>
        <source>node ids %1.. for %2 displays do not fit into 1..127</source>
        <translation>Knoten-IDs %1.. für %2 Anzeigen passen nicht in 1..127</translation>
    </message>
    <message>
        <source>the CAN bus %1 is not open</source>
        <translation>der CAN-Bus %1 ist nicht geöffnet</translation>
    </message>
    <message>
        <source>a display refused node id %1 (LSS error %2)</source>
        <translation>eine Anzeige hat Knoten-ID %1 abgelehnt (LSS-Fehler %2)</translation>
    </message>
    <message>
        <source>no display took node id %1 within %2 s</source>
        <translation>keine Anzeige hat Knoten-ID %1 innerhalb von %2 s übernommen</translation>
    </message>
</context>
<context>
    <name>db::nm17x::Nm17xSim</name>
    <message>
        <source>&apos;%1&apos; is not VARIANT@NODE (nm170, nm172 or nm174, node 1..127)</source>
        <translation>„%1“ ist nicht VARIANTE@KNOTEN (nm170, nm172 oder nm174, Knoten 1..127)</translation>
    </message>
    <message>
        <source>no displays given (e.g. nm172@127,nm174@5)</source>
        <translation>keine Anzeigen angegeben (z. B. nm172@127,nm174@5)</translation>
    </message>
    <message>
        <source>control port %1: %2</source>
        <translation>Steuer-Port %1: %2</translation>
    </message>
    <message>
        <source>empty command</source>
        <translation>leerer Befehl</translation>
    </message>
    <message>
        <source>give a display index 1..%1</source>
        <translation>einen Anzeigenindex 1..%1 angeben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a distance</source>
        <translation>„%1“ ist keine Strecke</translation>
    </message>
    <message>
        <source>key INDEX left|right [MS]</source>
        <translation>key INDEX left|right [MS] (Anzeigenindex, Taste, Dauer in ms)</translation>
    </message>
    <message>
        <source>only an NM174 has an external sensor</source>
        <translation>nur eine NM174 hat einen externen Sensor</translation>
    </message>
    <message>
        <source>input INDEX F G (each 0 or 1)</source>
        <translation>input INDEX F G (jeweils 0 oder 1)</translation>
    </message>
    <message>
        <source>fault INDEX motor|sensor|blocked|wiring|none</source>
        <translation>fault INDEX motor|sensor|blocked|wiring|none (Anzeigenindex, Störung)</translation>
    </message>
    <message>
        <source>glitch INDEX STEPS [READINGS]</source>
        <translation>glitch INDEX SCHRITTE [MESSUNGEN]</translation>
    </message>
    <message>
        <source>coast INDEX MS (0..10000)</source>
        <translation>coast INDEX MS (0..10000)</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (list, turn, key, fault, input, glitch, coast)</source>
        <translation>unbekannter Befehl „%1“ (list, turn, key, fault, input, glitch, coast)</translation>
    </message>
</context>
<context>
    <name>db::nm17x::SimulatedNm17x</name>
    <message>
        <source>no such object</source>
        <translation>kein solches Objekt</translation>
    </message>
    <message>
        <source>only 0 and 8 are allowed</source>
        <translation>nur 0 und 8 sind zulässig</translation>
    </message>
    <message>
        <source>only 0 clears the history</source>
        <translation>nur 0 löscht die Fehlerliste</translation>
    </message>
    <message>
        <source>wrong signature</source>
        <translation>falsche Signatur</translation>
    </message>
    <message>
        <source>transmission type not supported</source>
        <translation>Übertragungsart wird nicht unterstützt</translation>
    </message>
    <message>
        <source>exactly 12 characters</source>
        <translation>genau 12 Zeichen</translation>
    </message>
    <message>
        <source>11..13 or 21..23</source>
        <translation>11..13 oder 21..23</translation>
    </message>
    <message>
        <source>write queue to the application is full</source>
        <translation>Schreibwarteschlange zur Applikation ist voll</translation>
    </message>
    <message>
        <source>D3 cannot be written while input F is active</source>
        <translation>D3 kann nicht geschrieben werden, solange Eingang F aktiv ist</translation>
    </message>
</context>
<context>
    <name>db::refgo</name>
    <message>
        <source>command not supported</source>
        <translation>Befehl nicht unterstützt</translation>
    </message>
    <message>
        <source>RefGo client deleted</source>
        <translation>RefGo-Client gelöscht</translation>
    </message>
    <message>
        <source>a RefGo command is one line; CR and LF are not allowed</source>
        <translation>ein RefGo-Befehl ist eine Zeile; CR und LF sind nicht erlaubt</translation>
    </message>
    <message>
        <source>empty RefGo command</source>
        <translation>leerer RefGo-Befehl</translation>
    </message>
    <message>
        <source>RefGo command &apos;%1&apos; contains a non-printable or non-ASCII character</source>
        <translation>RefGo-Befehl „%1“ enthält ein nicht druckbares oder Nicht-ASCII-Zeichen</translation>
    </message>
    <message>
        <source>drive refused &apos;%1&apos;: %2</source>
        <translation>Antrieb hat „%1“ abgelehnt: %2</translation>
    </message>
    <message>
        <source>answer to &apos;%1&apos; %2</source>
        <translation>Antwort auf „%1“ %2</translation>
    </message>
    <message>
        <source>drive gave no value for &apos;%1&apos;</source>
        <translation>Antrieb hat keinen Wert für „%1“ geliefert</translation>
    </message>
    <message>
        <source>drive gave no value for &apos;%1&apos;: %2</source>
        <translation>Antrieb hat keinen Wert für „%1“ geliefert: %2</translation>
    </message>
    <message>
        <source>OW writes integers only, not %1 &apos;%2&apos;</source>
        <translation>OW schreibt nur Ganzzahlen, nicht %1 „%2“</translation>
    </message>
    <message>
        <source>drive did not acknowledge &apos;%1&apos; with &apos;,OK&apos;: %2</source>
        <translation>Antrieb hat „%1“ nicht mit „,OK“ bestätigt: %2</translation>
    </message>
    <message>
        <source>%1 %2 is %3: RefGo OR/OW carry integers only (use the CANopen SLCAN port for strings, domains and reals)</source>
        <translation>%1 %2 ist %3: RefGo OR/OW übertragen nur Ganzzahlen (für Zeichenketten, Domains und Gleitkommazahlen den CANopen-SLCAN-Port verwenden)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>not connected to %1</source>
        <translation>nicht mit %1 verbunden</translation>
    </message>
    <message>
        <source>answer too long without prompt (more than %1 bytes)</source>
        <translation>Antwort ohne Prompt zu lang (mehr als %1 Bytes)</translation>
    </message>
    <message>
        <source>RefGo server</source>
        <translation>RefGo-Server</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is too large</source>
        <translation>„%1“ ist zu groß</translation>
    </message>
    <message>
        <source>missing %1</source>
        <translation>%1 fehlt</translation>
    </message>
    <message>
        <source>%1 &apos;%2&apos; is not hexadecimal</source>
        <translation>%1 „%2“ ist nicht hexadezimal</translation>
    </message>
    <message>
        <source>%1 &apos;%2&apos; is too large</source>
        <translation>%1 „%2“ ist zu groß</translation>
    </message>
    <message>
        <source>value &apos;%1&apos; is too small</source>
        <translation>Wert „%1“ ist zu klein</translation>
    </message>
    <message>
        <source>third OR field must be &apos;h&apos; (hex output), not &apos;%1&apos;</source>
        <translation>drittes OR-Feld muss „h“ (Hex-Ausgabe) sein, nicht „%1“</translation>
    </message>
    <message>
        <source>empty request</source>
        <translation>leere Anfrage</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not start with a command</source>
        <translation>„%1“ beginnt nicht mit einem Befehl</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>unbekannter Befehl „%1“</translation>
    </message>
    <message>
        <source>%1 takes no parameter, got &apos;%2&apos;</source>
        <translation>%1 nimmt keinen Parameter, erhalten „%2“</translation>
    </message>
    <message>
        <source>%1 needs a numeric parameter</source>
        <translation>%1 braucht einen numerischen Parameter</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is too small</source>
        <translation>„%1“ ist zu klein</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an OR result line</source>
        <translation>„%1“ ist keine OR-Ergebniszeile</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no value field</source>
        <translation>„%1“ hat kein Wertfeld</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has more than three fields</source>
        <translation>„%1“ hat mehr als drei Felder</translation>
    </message>
    <message>
        <source>TPSR answer &apos;%1&apos; is not 8 hex digits</source>
        <translation>TPSR-Antwort „%1“ hat nicht 8 Hex-Ziffern</translation>
    </message>
    <message>
        <source>TS answer &apos;%1&apos; is not 0, 1, 2 or 9</source>
        <translation>TS-Antwort „%1“ ist nicht 0, 1, 2 oder 9</translation>
    </message>
    <message>
        <source>has %1 result lines, expected one: %2</source>
        <translation>hat %1 Ergebniszeilen, erwartet eine: %2</translation>
    </message>
    <message>
        <source>is not a number: %1</source>
        <translation>ist keine Zahl: %1</translation>
    </message>
    <message>
        <source>use objectRead()/objectWrite() for %1</source>
        <translation>für %1 objectRead()/objectWrite() verwenden</translation>
    </message>
    <message>
        <source>%1 takes no parameter</source>
        <translation>%1 nimmt keinen Parameter</translation>
    </message>
    <message>
        <source>%1 needs a parameter</source>
        <translation>%1 braucht einen Parameter</translation>
    </message>
    <message>
        <source>names object %1: &apos;%2&apos;</source>
        <translation>nennt Objekt %1: „%2“</translation>
    </message>
</context>
<context>
    <name>db::scope::PdoDiscovery</name>
    <message>
        <source>%1 is in no TPDO of node %2</source>
        <translation>%1 ist in keinem TPDO von Knoten %2</translation>
    </message>
    <message>
        <source>cannot read the PDO configuration: not connected</source>
        <translation>PDO-Konfiguration kann nicht gelesen werden: nicht verbunden</translation>
    </message>
    <message>
        <source>PDOs need a connection to a CANopen node</source>
        <translation>PDOs brauchen eine Verbindung zu einem CANopen-Knoten</translation>
    </message>
    <message>
        <source>reading the PDO configuration of node %1</source>
        <translation>Lesen der PDO-Konfiguration von Knoten %1</translation>
    </message>
    <message>
        <source>%1 has no event timer and is sent only on device events</source>
        <translation>%1 hat keinen Event-Timer und wird nur bei Geräteereignissen gesendet</translation>
    </message>
    <message>
        <source>%1 is sent on SYNC (transmission type %2) and no SYNC was produced</source>
        <translation>%1 wird auf SYNC gesendet (Übertragungsart %2), aber es wurde kein SYNC erzeugt</translation>
    </message>
    <message>
        <source>%1 is sent only on events or remote requests (type 0x%2)</source>
        <translation>%1 wird nur bei Ereignissen oder Remote-Anfragen gesendet (Art 0x%2)</translation>
    </message>
    <message>
        <source>node %1 is operational (heartbeat), yet its TPDOs did not come</source>
        <translation>Knoten %1 ist operational (Heartbeat), seine TPDOs kamen aber nicht</translation>
    </message>
    <message>
        <source>node %1 is operational (heartbeat), but %2</source>
        <translation>Knoten %1 ist operational (Heartbeat), aber %2</translation>
    </message>
    <message>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <source>node %1 is pre-operational (heartbeat), not operational: NMT start it</source>
        <translation>Knoten %1 ist pre-operational (Heartbeat), nicht operational: per NMT starten</translation>
    </message>
    <message>
        <source>node %1 is stopped (heartbeat), not operational: NMT start it</source>
        <translation>Knoten %1 ist gestoppt (Heartbeat), nicht operational: per NMT starten</translation>
    </message>
    <message>
        <source>node %1 is probably not operational (no heartbeat heard): NMT start it</source>
        <translation>Knoten %1 ist wahrscheinlich nicht operational (kein Heartbeat empfangen): per NMT starten</translation>
    </message>
    <message>
        <source>; or %1</source>
        <translation>; oder %1</translation>
    </message>
    <message>
        <source>; or </source>
        <translation>; oder </translation>
    </message>
</context>
<context>
    <name>db::scope::PdoSource</name>
    <message>
        <source>cannot add a channel while sampling</source>
        <translation>während der Abtastung kann kein Kanal hinzugefügt werden</translation>
    </message>
    <message>
        <source>%1: only numeric types can be sampled from a PDO</source>
        <translation>%1: nur numerische Typen können aus einem PDO abgetastet werden</translation>
    </message>
    <message>
        <source>%1: bytes %2..%3 do not fit into a CAN frame of 8 bytes</source>
        <translation>%1: Bytes %2..%3 passen nicht in einen CAN-Frame mit 8 Bytes</translation>
    </message>
    <message>
        <source>%1: bad COB-ID or period</source>
        <translation>%1: ungültige COB-ID oder Periode</translation>
    </message>
    <message>
        <source>%1 is not enabled (COB-ID bit 31 set)</source>
        <translation>%1 ist nicht aktiviert (COB-ID Bit 31 gesetzt)</translation>
    </message>
    <message>
        <source>cannot sample PDOs: the CAN bus is not open</source>
        <translation>PDOs können nicht abgetastet werden: der CAN-Bus ist nicht geöffnet</translation>
    </message>
    <message>
        <source>PDO sampling stopped</source>
        <translation>PDO-Abtastung gestoppt</translation>
    </message>
    <message>
        <source>PDO sampling stopped: the CAN bus was closed</source>
        <translation>PDO-Abtastung gestoppt: der CAN-Bus wurde geschlossen</translation>
    </message>
    <message>
        <source>TPDO number out of range</source>
        <translation>TPDO-Nummer außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>TPDO%1 has no predefined COB-ID; give one</source>
        <translation>TPDO%1 hat keine vordefinierte COB-ID; eine angeben</translation>
    </message>
    <message>
        <source>node id must be 1..127</source>
        <translation>Knoten-ID muss 1..127 sein</translation>
    </message>
    <message>
        <source>event timer must be 0..65535 ms</source>
        <translation>Event-Timer muss 0..65535 ms sein</translation>
    </message>
    <message>
        <source>no objects to map</source>
        <translation>keine Objekte zum Mappen</translation>
    </message>
    <message>
        <source>%1 is not a numeric object of the description</source>
        <translation>%1 ist kein numerisches Objekt der Beschreibung</translation>
    </message>
    <message>
        <source>the objects need %1 bits; a PDO carries at most 64</source>
        <translation>die Objekte brauchen %1 Bit; ein PDO trägt höchstens 64</translation>
    </message>
    <message>
        <source>no PDO client</source>
        <translation>kein PDO-Client</translation>
    </message>
</context>
<context>
    <name>db::scope::PollingSource</name>
    <message>
        <source>the connection was closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
    <message>
        <source>no connection to poll</source>
        <translation>keine Verbindung zum Abfragen</translation>
    </message>
    <message>
        <source>cannot add a channel while sampling</source>
        <translation>während der Abtastung kann kein Kanal hinzugefügt werden</translation>
    </message>
    <message>
        <source>%1: the sample period must be &gt;= 0 ms</source>
        <translation>%1: die Abtastperiode muss &gt;= 0 ms sein</translation>
    </message>
    <message>
        <source>%1 (%2) is write-only</source>
        <translation>%1 (%2) ist nur schreibbar</translation>
    </message>
    <message>
        <source>%1 (%2) is not a number and cannot be recorded</source>
        <translation>%1 (%2) ist keine Zahl und kann nicht aufgezeichnet werden</translation>
    </message>
    <message>
        <source>cannot sample %1: not connected</source>
        <translation>%1 kann nicht abgetastet werden: nicht verbunden</translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation>Lesen von %1</translation>
    </message>
    <message>
        <source>%1: the answer is not a number</source>
        <translation>%1: die Antwort ist keine Zahl</translation>
    </message>
    <message>
        <source>sampling stopped</source>
        <translation>Abtastung gestoppt</translation>
    </message>
</context>
<context>
    <name>db::scope::Recorder</name>
    <message>
        <source>no channels to record</source>
        <translation>keine Kanäle zum Aufzeichnen</translation>
    </message>
    <message>
        <source>single and normal mode need a trigger on a recorded channel with pre/post times &gt;= 0</source>
        <translation>Einzel- und Normalbetrieb brauchen einen Trigger auf einem aufgezeichneten Kanal mit Vor-/Nachlaufzeiten &gt;= 0</translation>
    </message>
    <message>
        <source>channel %1 has no source (loaded from a file or its source was closed)</source>
        <translation>Kanal %1 hat keine Quelle (aus einer Datei geladen, oder seine Quelle wurde geschlossen)</translation>
    </message>
</context>
<context>
    <name>db::scope::Trigger</name>
    <message>
        <source>missing condition</source>
        <translation>Bedingung fehlt</translation>
    </message>
    <message>
        <source>%1 is not one of the recorded channels</source>
        <translation>%1 ist keiner der aufgezeichneten Kanäle</translation>
    </message>
    <message>
        <source>bit number must be 0..63</source>
        <translation>Bitnummer muss 0..63 sein</translation>
    </message>
    <message>
        <source>a bit trigger ends in &apos;set&apos; or &apos;clear&apos;</source>
        <translation>ein Bit-Trigger endet auf „set“ oder „clear“</translation>
    </message>
    <message numerus="yes">
        <source>&apos;%1&apos; takes %n number(s)</source>
        <translation>
            <numerusform>„%1“ erwartet %n Zahl</numerusform>
            <numerusform>„%1“ erwartet %n Zahlen</numerusform>
        </translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>window low bound above the high bound</source>
        <translation>untere Fenstergrenze liegt über der oberen</translation>
    </message>
    <message>
        <source>unknown condition &apos;%1&apos;</source>
        <translation>unbekannte Bedingung „%1“</translation>
    </message>
    <message>
        <source>trigger &apos;%1&apos;: %2 (expected CHANNEL,rising|falling|above|below,LEVEL or CHANNEL,inside|outside,LOW,HIGH or CHANNEL,bitN,set|clear)</source>
        <translation>Trigger „%1“: %2 (erwartet KANAL,rising|falling|above|below,PEGEL oder KANAL,inside|outside,UNTEN,OBEN oder KANAL,bitN,set|clear)</translation>
    </message>
</context>
<context>
    <name>db::scope::analysis</name>
    <message>
        <source>a spectrum needs at least %1 samples in the range (has %2)</source>
        <translation>ein Spektrum braucht mindestens %1 Messwerte im Bereich (vorhanden: %2)</translation>
    </message>
    <message>
        <source>the samples in the range have no time spacing</source>
        <translation>die Messwerte im Bereich haben keinen zeitlichen Abstand</translation>
    </message>
    <message>
        <source>the range is too short for a spectrum</source>
        <translation>der Bereich ist für ein Spektrum zu kurz</translation>
    </message>
    <message>
        <source>a step response needs at least 3 samples in the range (has %1)</source>
        <translation>eine Sprungantwort braucht mindestens 3 Messwerte im Bereich (vorhanden: %1)</translation>
    </message>
    <message>
        <source>not a step: the first and the final value are equal</source>
        <translation>kein Sprung: erster Wert und Endwert sind gleich</translation>
    </message>
    <message>
        <source>not a step: the signal swings more than it moves from its first to its final value</source>
        <translation>kein Sprung: das Signal schwankt stärker, als es sich vom ersten zum Endwert bewegt</translation>
    </message>
    <message>
        <source>not a step: the signal has not settled at the end of the range</source>
        <translation>kein Sprung: das Signal hat sich am Ende des Bereichs nicht eingeschwungen</translation>
    </message>
    <message>
        <source>not a step: the signal does not pass from 10 % to 90 % of the step in the range</source>
        <translation>kein Sprung: das Signal durchläuft im Bereich nicht 10 % bis 90 % des Sprungs</translation>
    </message>
</context>
<context>
    <name>db::scope::csv</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>bad trigger detail &apos;%1&apos;</source>
        <translation>ungültige Trigger-Angabe „%1“</translation>
    </message>
    <message>
        <source>not a drivebench recording (the first line must be &apos;# drivebench recording v1&apos;)</source>
        <translation>keine drivebench-Aufzeichnung (die erste Zeile muss „# drivebench recording v1“ sein)</translation>
    </message>
    <message>
        <source>bad start time &apos;%1&apos;</source>
        <translation>ungültige Startzeit „%1“</translation>
    </message>
    <message>
        <source>channel %1: bad scale or offset</source>
        <translation>Kanal %1: ungültige Skalierung oder ungültiger Offset</translation>
    </message>
    <message>
        <source>bad gap time &apos;%1&apos;</source>
        <translation>ungültige Lückenzeit „%1“</translation>
    </message>
    <message>
        <source>no &apos;# channel:&apos; lines before the data</source>
        <translation>keine „# channel:“-Zeilen vor den Daten</translation>
    </message>
    <message>
        <source>missing the column header &apos;time_s,...&apos;</source>
        <translation>Spaltenkopf „time_s,...“ fehlt</translation>
    </message>
    <message>
        <source>%1 cells, expected %2 (time and one per channel)</source>
        <translation>%1 Zellen, erwartet %2 (Zeit und eine je Kanal)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a time in seconds</source>
        <translation>„%1“ ist keine Zeit in Sekunden</translation>
    </message>
    <message>
        <source>time goes back (%1 s after a later row)</source>
        <translation>die Zeit läuft rückwärts (%1 s nach einer späteren Zeile)</translation>
    </message>
    <message>
        <source>column %1 (%2): &apos;%3&apos; is not a number</source>
        <translation>Spalte %1 (%2): „%3“ ist keine Zahl</translation>
    </message>
    <message>
        <source>channel %1: unknown address format &apos;%2&apos; (canopen or parameter)</source>
        <translation>Kanal %1: unbekanntes Adressformat &apos;%2&apos; (canopen oder parameter)</translation>
    </message>
    <message>
        <source>channel line without a valid id (%1 addresses are written like %2)</source>
        <translation>Kanalzeile ohne gültige Kennung (%1-Adressen werden wie %2 geschrieben)</translation>
    </message>
    <message>
        <source>a recording</source>
        <translation>eine Aufzeichnung</translation>
    </message>
    <message>
        <source>bad gap line &apos;%1&apos;</source>
        <translation>ungültige Lückenzeile „%1“</translation>
    </message>
</context>
<context>
    <name>db::sim</name>
    <message>
        <source>the MovingCap has no object %1</source>
        <translation>der MovingCap hat kein Objekt %1</translation>
    </message>
</context>
<context>
    <name>db::simulation</name>
    <message>
        <source>software enable missing (FFF2h), drive in fault state</source>
        <translation>Software-Freigabe fehlt (FFF2h), Antrieb im Störungszustand</translation>
    </message>
    <message>
        <source>drive cannot be switched on</source>
        <translation>Antrieb kann nicht eingeschaltet werden</translation>
    </message>
    <message>
        <source>drive in fault state</source>
        <translation>Antrieb im Störungszustand</translation>
    </message>
    <message>
        <source>nothing to continue</source>
        <translation>nichts fortzusetzen</translation>
    </message>
    <message>
        <source>homing method %1 is not supported</source>
        <translation>Referenzfahrtmethode %1 wird nicht unterstützt</translation>
    </message>
    <message>
        <source>%1 refused in the present device state (simulated)</source>
        <translation>%1 im aktuellen Gerätezustand abgelehnt (simuliert)</translation>
    </message>
    <message>
        <source>1010:1 expects 1702257011 (&apos;save&apos;)</source>
        <translation>1010:1 erwartet 1702257011 („save“)</translation>
    </message>
    <message>
        <source>1011:1 expects 1684107116 (&apos;load&apos;)</source>
        <translation>1011:1 erwartet 1684107116 („load“)</translation>
    </message>
    <message>
        <source>3510:2 input number %1 is not 1..10</source>
        <translation>3510:2 Eingangsnummer %1 liegt nicht in 1..10</translation>
    </message>
    <message>
        <source>object %1 does not exist</source>
        <translation>Objekt %1 existiert nicht</translation>
    </message>
    <message>
        <source>%1 is write-only</source>
        <translation>%1 ist nur schreibbar</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 ist nur lesbar</translation>
    </message>
</context>
<context>
    <name>db::transport</name>
    <message>
        <source>%1 did not open within %2 ms</source>
        <translation>%1 wurde nicht innerhalb von %2 ms geöffnet</translation>
    </message>
    <message>
        <source>no Qt CAN plugin &apos;%1&apos; for interface %2 (available plugins: %3)</source>
        <translation>kein Qt-CAN-Plugin „%1“ für Schnittstelle %2 (vorhandene Plugins: %3)</translation>
    </message>
    <message>
        <source>cannot create %1 interface &apos;%2&apos;: %3 (available: %4)</source>
        <translation>%1-Schnittstelle „%2“ kann nicht angelegt werden: %3 (vorhanden: %4)</translation>
    </message>
    <message>
        <source>cannot open %1 interface &apos;%2&apos;: %3</source>
        <translation>%1-Schnittstelle „%2“ kann nicht geöffnet werden: %3</translation>
    </message>
    <message>
        <source>%1 closed unexpectedly</source>
        <translation>%1 wurde unerwartet geschlossen</translation>
    </message>
    <message>
        <source>cannot send &apos;%1&apos;: not connected to %2</source>
        <translation>„%1“ kann nicht gesendet werden: nicht mit %2 verbunden</translation>
    </message>
    <message>
        <source>answer from %1 does not belong to &apos;%2&apos;: %3</source>
        <translation>Antwort von %1 gehört nicht zu „%2“: %3</translation>
    </message>
    <message>
        <source>connection to %1 closed</source>
        <translation>Verbindung zu %1 geschlossen</translation>
    </message>
    <message>
        <source>slcan server</source>
        <translation>SLCAN-Server</translation>
    </message>
    <message>
        <source>%1 already listens on port %2</source>
        <translation>%1 lauscht bereits auf Port %2</translation>
    </message>
    <message>
        <source>%1 cannot listen on %2:%3: %4</source>
        <translation>%1 kann nicht auf %2:%3 lauschen: %4</translation>
    </message>
    <message>
        <source>no TCP connection to %1 within %2 ms</source>
        <translation>keine TCP-Verbindung zu %1 innerhalb von %2 ms</translation>
    </message>
    <message>
        <source>%1 closed the connection</source>
        <translation>%1 hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <source>%1 refused the connection (nothing listens on that port)</source>
        <translation>%1 hat die Verbindung abgelehnt (an diesem Port lauscht niemand)</translation>
    </message>
    <message>
        <source>host &apos;%1&apos; not found</source>
        <translation>Host „%1“ nicht gefunden</translation>
    </message>
    <message>
        <source>%1: socket timeout</source>
        <translation>%1: Zeitüberschreitung des Sockets</translation>
    </message>
    <message>
        <source>%1: network error: %2</source>
        <translation>%1: Netzwerkfehler: %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: receive queue overflow: %2 frames dropped (%3 in all)</source>
        <translation>%1: Überlauf der Empfangswarteschlange: %2 Frames verworfen (insgesamt %3)</translation>
    </message>
    <message>
        <source>dropping client %1:%2: it has not read its answers for %3 ms (%4 bytes queued)</source>
        <translation>trenne Client %1:%2: er hat seine Antworten seit %3 ms nicht gelesen (%4 Bytes in der Warteschlange)</translation>
    </message>
    <message>
        <source>%1: frame %2 not sent: %3</source>
        <translation>%1: Frame %2 nicht gesendet: %3</translation>
    </message>
    <message>
        <source>%1: connection error: %2</source>
        <translation>%1: Verbindungsfehler: %2</translation>
    </message>
    <message>
        <source>%1: configuration not applied (bit rate %2): %3</source>
        <translation>%1: Konfiguration nicht übernommen (Bitrate %2): %3</translation>
    </message>
    <message>
        <source>%1: error frame: %2</source>
        <translation>%1: Error-Frame: %2</translation>
    </message>
    <message>
        <source>no answer to &apos;%1&apos; from %2 within %3 ms</source>
        <translation>keine Antwort auf „%1“ von %2 innerhalb von %3 ms</translation>
    </message>
    <message>
        <source> (sent %1 times)</source>
        <translation> (%1-mal gesendet)</translation>
    </message>
    <message>
        <source>%1: cannot send frame %2 over slcan (FD, error frame or more than 8 bytes)</source>
        <translation>%1: Frame %2 kann nicht über SLCAN gesendet werden (FD, Error-Frame oder mehr als 8 Bytes)</translation>
    </message>
    <message>
        <source>%1: the adapter answered BEL (command or frame refused)</source>
        <translation>%1: der Adapter hat mit BEL geantwortet (Befehl oder Frame abgelehnt)</translation>
    </message>
    <message>
        <source>%1: skipped a line that is not slcan: &apos;%2&apos;</source>
        <translation>%1: Zeile übersprungen, die kein SLCAN ist: „%2“</translation>
    </message>
    <message>
        <source>reconnecting to %1</source>
        <translation>erneutes Verbinden mit %1</translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation>mit %1 verbunden</translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation>Verbinden mit %1</translation>
    </message>
    <message>
        <source>disconnected from %1</source>
        <translation>Verbindung zu %1 getrennt</translation>
    </message>
    <message>
        <source>CAN interface &apos;%1&apos; does not exist for plugin %2 (available: %3)</source>
        <translation>CAN-Schnittstelle „%1“ gibt es für das Plugin %2 nicht (vorhanden: %3)</translation>
    </message>
    <message>
        <source>cannot use %1 interface &apos;%2&apos;: %3 (available: %4)</source>
        <translation>%1-Schnittstelle „%2“ ist nicht verwendbar: %3 (vorhanden: %4)</translation>
    </message>
    <message>
        <source>%1: cannot take over the connection: %2</source>
        <translation>%1: Verbindung kann nicht übernommen werden: %2</translation>
    </message>
</context>
<context>
    <name>db::vabus</name>
    <message>
        <source>VABus writes data sets 0-9, not %1</source>
        <translation>VABus schreibt die Datensätze 0-9, nicht %1</translation>
    </message>
    <message>
        <source>inverter refused write of %1: VABus error %2, %3</source>
        <translation>Umrichter hat das Schreiben von %1 abgelehnt: VABus-Fehler %2, %3</translation>
    </message>
    <message>
        <source>inverter refused read of %1: VABus error %2, %3</source>
        <translation>Umrichter hat das Lesen von %1 abgelehnt: VABus-Fehler %2, %3</translation>
    </message>
    <message>
        <source>connecting to %1 again (the inverter may be starting up)</source>
        <translation>erneutes Verbinden mit %1 (der Umrichter startet eventuell gerade)</translation>
    </message>
    <message>
        <source>VABus server</source>
        <translation>VABus-Server</translation>
    </message>
    <message>
        <source>refusing the connection from %1:%2: the PLC port takes one connection and %3:%4 holds it</source>
        <translation>Verbindung von %1:%2 abgewiesen: der SPS-Port nimmt eine Verbindung an, und %3:%4 hält sie</translation>
    </message>
</context>
<context>
    <name>db::widgets::CanMonitor</name>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Freeze the table; frames are still captured and appear when you resume</source>
        <translation>Tabelle anhalten; Frames werden weiter erfasst und erscheinen beim Fortsetzen</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Forget every frame</source>
        <translation>Alle Frames verwerfen</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Save the frames shown as a candump log</source>
        <translation>Die angezeigten Frames als candump-Protokoll speichern</translation>
    </message>
    <message>
        <source>Autoscroll</source>
        <translation>Automatisch scrollen</translation>
    </message>
    <message>
        <source>580-5FF, 81-FF</source>
        <translation>580-5FF, 81-FF</translation>
    </message>
    <message>
        <source>COB-IDs in hex: single ids and ranges, comma separated</source>
        <translation>COB-IDs hexadezimal: einzelne IDs und Bereiche, durch Komma getrennt</translation>
    </message>
    <message>
        <source>RX + TX</source>
        <translation>RX + TX</translation>
    </message>
    <message>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <source>6041</source>
        <translation>6041</translation>
    </message>
    <message>
        <source>Object index (hex), optionally :sub-index: SDO traffic of this object</source>
        <translation>Objektindex (hex), optional :Subindex: SDO-Verkehr dieses Objekts</translation>
    </message>
    <message>
        <source>4B 41 60 ?? 27</source>
        <translation>4B 41 60 ?? 27</translation>
    </message>
    <message>
        <source>Data from byte 0 in hex; ?? matches any byte, ? any digit</source>
        <translation>Daten ab Byte 0 hexadezimal; ?? passt auf jedes Byte, ? auf jede Ziffer</translation>
    </message>
    <message>
        <source>Search decoded text</source>
        <translation>Dekodierten Text durchsuchen</translation>
    </message>
    <message>
        <source>Text in the service or the CANopen reading</source>
        <translation>Text im Dienst oder in der CANopen-Deutung</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Object index (hex), optionally :sub-index</source>
        <translation>Objektindex (hex), optional :Subindex</translation>
    </message>
    <message>
        <source>%1 frames</source>
        <translation>%1 Frames</translation>
    </message>
    <message>
        <source>, %1 shown</source>
        <translation>, %1 angezeigt</translation>
    </message>
    <message>
        <source>, %1 oldest dropped</source>
        <translation>, %1 älteste verworfen</translation>
    </message>
    <message>
        <source> — paused, %1 waiting</source>
        <translation> — angehalten, %1 wartend</translation>
    </message>
    <message>
        <source> — no CAN bus</source>
        <translation> — kein CAN-Bus</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Save CAN log</source>
        <translation>CAN-Protokoll speichern</translation>
    </message>
    <message>
        <source>candump logs (*.log);;All files (*)</source>
        <translation>candump-Protokolle (*.log);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>db::widgets::CanMonitorModel</name>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>Richt.</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Len</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <source>Service</source>
        <translation>Dienst</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>CANopen</source>
        <translation>CANopen</translation>
    </message>
    <message>
        <source>remote request</source>
        <translation>Remote-Anfrage</translation>
    </message>
</context>
<context>
    <name>db::widgets::ChangeLogModel</name>
    <message>
        <source>In the device&apos;s working memory only: lost at power-off until the device stores its parameters permanently.</source>
        <translation>Nur im Arbeitsspeicher des Geräts: beim Ausschalten verloren, bis das Gerät seine Parameter dauerhaft speichert.</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Old value</source>
        <translation>Alter Wert</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Stored</source>
        <translation>Gespeichert</translation>
    </message>
</context>
<context>
    <name>db::widgets::ChangeLogView</name>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Save the change log as a CSV file</source>
        <translation>Das Änderungsprotokoll als CSV-Datei speichern</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Writes, restores, stores, enables, motion and NMT commands of this session appear here.</source>
        <translation>Schreibzugriffe, Wiederherstellungen, Speichern, Freigaben, Bewegungs- und NMT-Befehle dieser Sitzung erscheinen hier.</translation>
    </message>
    <message numerus="yes">
        <source>%n change(s)</source>
        <translation>
            <numerusform>%n Änderung</numerusform>
            <numerusform>%n Änderungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n failed</source>
        <translation>
            <numerusform>%n fehlgeschlagen</numerusform>
            <numerusform>%n fehlgeschlagen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n write(s) not stored permanently</source>
        <translation>
            <numerusform>%n Schreibzugriff nicht dauerhaft gespeichert</numerusform>
            <numerusform>%n Schreibzugriffe nicht dauerhaft gespeichert</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved to %1</source>
        <translation>Gespeichert in %1</translation>
    </message>
    <message>
        <source>Save change log</source>
        <translation>Änderungsprotokoll speichern</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
</context>
<context>
    <name>db::widgets::ConnectionDialog</name>
    <message>
        <source>Connect to Device</source>
        <translation>Mit Gerät verbinden</translation>
    </message>
    <message>
        <source>IP address, host name or CAN interface</source>
        <translation>IP-Adresse, Hostname oder CAN-Schnittstelle</translation>
    </message>
    <message>
        <source>e.g. node=50&amp;bitrate=500000</source>
        <translation>z. B. node=50&amp;bitrate=500000</translation>
    </message>
    <message>
        <source>scheme://host[:port][?key=value]</source>
        <translation>schema://host[:port][?schlüssel=wert]</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protokoll:</translation>
    </message>
    <message>
        <source>&amp;Address:</source>
        <translation>&amp;Adresse:</translation>
    </message>
    <message>
        <source>P&amp;ort:</source>
        <translation>P&amp;ort:</translation>
    </message>
    <message>
        <source>O&amp;ptions:</source>
        <translation>O&amp;ptionen:</translation>
    </message>
    <message>
        <source>&amp;URI:</source>
        <translation>&amp;URI:</translation>
    </message>
    <message>
        <source>Recent connections</source>
        <translation>Letzte Verbindungen</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Enter an address or a connection URI.</source>
        <translation>Adresse oder Verbindungs-URI eingeben.</translation>
    </message>
    <message>
        <source>Connects to %1</source>
        <translation>Verbindet mit %1</translation>
    </message>
    <message>
        <source>not set</source>
        <translation>nicht gesetzt</translation>
    </message>
    <message>
        <source>CANopen node id of the device (1..127)</source>
        <translation>CANopen-Knotennummer des Geräts (1..127)</translation>
    </message>
    <message>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <source>Automatic by identity (1018h)</source>
        <translation>Automatisch nach Identität (1018h)</translation>
    </message>
    <message>
        <source>Other file…</source>
        <translation>Andere Datei…</translation>
    </message>
    <message>
        <source>Automatic: the description library&apos;s file for the vendor, product and revision the node reports. Or a description file for this connection.</source>
        <translation>Automatisch: die Datei der Beschreibungsbibliothek für Hersteller, Produkt und Revision, die der Knoten meldet. Oder eine Beschreibungsdatei für diese Verbindung.</translation>
    </message>
    <message>
        <source>&amp;Node:</source>
        <translation>&amp;Knoten:</translation>
    </message>
    <message>
        <source>&amp;Bit rate:</source>
        <translation>&amp;Bitrate:</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>&amp;Beschreibung:</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Description of the device</source>
        <translation>Beschreibung des Geräts</translation>
    </message>
    <message>
        <source>&amp;Interface:</source>
        <translation>&amp;Schnittstelle:</translation>
    </message>
    <message>
        <source>default (%1 kbit/s)</source>
        <translation>Standard (%1 kbit/s)</translation>
    </message>
    <message>
        <source>as the interface is set</source>
        <translation>wie an der Schnittstelle eingestellt</translation>
    </message>
    <message>
        <source>no interface found; type its name</source>
        <translation>keine Schnittstelle gefunden; Namen eingeben</translation>
    </message>
    <message>
        <source>no interface found (%1); type its name</source>
        <translation>keine Schnittstelle gefunden (%1); Namen eingeben</translation>
    </message>
    <message>
        <source>choose an interface: %1</source>
        <translation>Schnittstelle wählen: %1</translation>
    </message>
    <message>
        <source>IP address or host name of the SLCAN gateway</source>
        <translation>IP-Adresse oder Hostname des SLCAN-Gateways</translation>
    </message>
    <message>
        <source>IP address or host name</source>
        <translation>IP-Adresse oder Hostname</translation>
    </message>
</context>
<context>
    <name>db::widgets::DescriptionLibraryDialog</name>
    <message>
        <source>Add…</source>
        <translation>Hinzufügen…</translation>
    </message>
    <message>
        <source>Description Library</source>
        <translation>Beschreibungsbibliothek</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Vendor</source>
        <translation>Hersteller</translation>
    </message>
    <message>
        <source>Product</source>
        <translation>Produkt</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Copy a description file (EDS, DCF, XDD, XDC or drivebench JSON) into the library folder; you can also drop files here</source>
        <translation>Eine Beschreibungsdatei (EDS, DCF, XDD, XDC oder drivebench-JSON) in den Bibliotheksordner kopieren; Dateien können auch hierher gezogen werden</translation>
    </message>
    <message>
        <source>Add descriptions to the library</source>
        <translation>Beschreibungen zur Bibliothek hinzufügen</translation>
    </message>
    <message>
        <source>No library folder is set; only the built-in descriptions are used.</source>
        <translation>Kein Bibliotheksordner gesetzt; nur die eingebauten Beschreibungen werden verwendet.</translation>
    </message>
    <message>
        <source>Devices without a description given get the one whose vendor, product and revision match their identity (1018h). Your files are in %1.</source>
        <translation>Geräte ohne angegebene Beschreibung erhalten die, deren Hersteller, Produkt und Revision zu ihrer Identität (1018h) passen. Ihre Dateien liegen in %1.</translation>
    </message>
    <message>
        <source>any</source>
        <translation>beliebig</translation>
    </message>
    <message>
        <source>built-in</source>
        <translation>eingebaut</translation>
    </message>
    <message>
        <source>Not used: %1</source>
        <translation>Nicht verwendet: %1</translation>
    </message>
    <message>
        <source>%1 not added: %2</source>
        <translation>%1 nicht hinzugefügt: %2</translation>
    </message>
    <message>
        <source>%1 added to the library</source>
        <translation>%1 zur Bibliothek hinzugefügt</translation>
    </message>
</context>
<context>
    <name>db::widgets::DescriptionPrompt</name>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Choose the device&apos;s description file (EDS, DCF, XDD, XDC or drivebench JSON); it is also added to the description library</source>
        <translation>Die Beschreibungsdatei des Geräts wählen (EDS, DCF, XDD, XDC oder drivebench-JSON); sie wird auch in die Beschreibungsbibliothek aufgenommen</translation>
    </message>
    <message>
        <source>Description of the device</source>
        <translation>Beschreibung des Geräts</translation>
    </message>
    <message>
        <source>Device descriptions (*.eds *.dcf *.xdd *.xdc *.json);;All files (*)</source>
        <translation>Gerätebeschreibungen (*.eds *.dcf *.xdd *.xdc *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>It reports vendor %1, product %2</source>
        <translation>Es meldet Hersteller %1, Produkt %2</translation>
    </message>
    <message>
        <source>, revision %1.</source>
        <translation>, Revision %1.</translation>
    </message>
    <message>
        <source>It did not report its identity (1018h).</source>
        <translation>Es hat seine Identität (1018h) nicht gemeldet.</translation>
    </message>
    <message>
        <source>&lt;b&gt;No description for this device.&lt;/b&gt; %1 No description in the library matches it, so its objects are not listed; read and write them with &lt;i&gt;By index…&lt;/i&gt;, or choose its description file (Browse… or drop it here).</source>
        <translation>&lt;b&gt;Keine Beschreibung für dieses Gerät.&lt;/b&gt; %1 Keine Beschreibung in der Bibliothek passt dazu, daher werden seine Objekte nicht aufgelistet; lesen und schreiben Sie sie mit &lt;i&gt;Nach Index…&lt;/i&gt;, oder wählen Sie seine Beschreibungsdatei (Durchsuchen… oder hierher ziehen).</translation>
    </message>
</context>
<context>
    <name>db::widgets::DeviceList</name>
    <message>
        <source>Add…</source>
        <translation>Hinzufügen…</translation>
    </message>
    <message>
        <source>Open a new connection</source>
        <translation>Neue Verbindung öffnen</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Connect the selected device</source>
        <translation>Ausgewähltes Gerät verbinden</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Disconnect the selected device</source>
        <translation>Ausgewähltes Gerät trennen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Close and remove the selected device</source>
        <translation>Ausgewähltes Gerät schließen und entfernen</translation>
    </message>
    <message>
        <source>%1
State: %2</source>
        <translation>%1
Zustand: %2</translation>
    </message>
    <message>
        <source>
Last error: %1</source>
        <translation>
Letzter Fehler: %1</translation>
    </message>
</context>
<context>
    <name>db::widgets::DriveStatusPanel</name>
    <message>
        <source>No device selected.</source>
        <translation>Kein Gerät ausgewählt.</translation>
    </message>
    <message>
        <source>%1 is %2.</source>
        <translation>%1 ist %2.</translation>
    </message>
    <message numerus="yes">
        <source>%n read(s) failed; %1: %2</source>
        <translation>
            <numerusform>%n Lesevorgang fehlgeschlagen; %1: %2</numerusform>
            <numerusform>%n Lesevorgänge fehlgeschlagen; %1: %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Updated %1, every %2 ms</source>
        <translation>Aktualisiert %1, alle %2 ms</translation>
    </message>
    <message>
        <source>No status</source>
        <translation>Kein Status</translation>
    </message>
    <message>
        <source>No error or warning bits</source>
        <translation>Keine Fehler- oder Warnbits</translation>
    </message>
    <message>
        <source>Drive state</source>
        <translation>Antriebszustand</translation>
    </message>
    <message>
        <source>Statusword:</source>
        <translation>Statuswort:</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Modus:</translation>
    </message>
    <message>
        <source>Actual values</source>
        <translation>Istwerte</translation>
    </message>
    <message>
        <source>Faults</source>
        <translation>Störungen</translation>
    </message>
    <message>
        <source>Digital I/O</source>
        <translation>Digitale E/A</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Warnings:</source>
        <translation>Warnungen:</translation>
    </message>
    <message>
        <source>Fault:</source>
        <translation>Störung:</translation>
    </message>
</context>
<context>
    <name>db::widgets::FrameSender</name>
    <message>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>CAN identifier in hex (above 7FF: 29-bit)</source>
        <translation>CAN-Identifier hexadezimal (über 7FF: 29 Bit)</translation>
    </message>
    <message>
        <source>data bytes, e.g. 01 05</source>
        <translation>Datenbytes, z. B. 01 05</translation>
    </message>
    <message>
        <source>Up to 8 data bytes in hex</source>
        <translation>Bis zu 8 Datenbytes hexadezimal</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>Send the frame once</source>
        <translation>Den Frame einmal senden</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Period of periodic sending</source>
        <translation>Periode des zyklischen Sendens</translation>
    </message>
    <message>
        <source>Periodic</source>
        <translation>Zyklisch</translation>
    </message>
    <message>
        <source>Send the frame every period until switched off</source>
        <translation>Den Frame in jeder Periode senden, bis ausgeschaltet</translation>
    </message>
    <message>
        <source>Macro…</source>
        <translation>Makro…</translation>
    </message>
    <message>
        <source>A list of send ID DATA and wait MS lines</source>
        <translation>Eine Liste von Zeilen send ID DATEN und wait MS</translation>
    </message>
    <message>
        <source># one step a line
send 000 01 05
wait 100
send 605 40 08 10 00</source>
        <translation># ein Schritt je Zeile
send 000 01 05
wait 100
send 605 40 08 10 00</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no CAN identifier (hex, 0..1FFFFFFF)</source>
        <translation>&apos;%1&apos; ist kein CAN-Identifier (hexadezimal, 0..1FFFFFFF)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; are no data bytes (hex, e.g. 01 05)</source>
        <translation>&apos;%1&apos; sind keine Datenbytes (hexadezimal, z. B. 01 05)</translation>
    </message>
    <message>
        <source>%1 data bytes; a CAN frame carries at most 8</source>
        <translation>%1 Datenbytes; ein CAN-Frame trägt höchstens 8</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>%1: send needs an ID and data bytes</source>
        <translation>%1: send braucht eine ID und Datenbytes</translation>
    </message>
    <message>
        <source>%1: wait takes milliseconds (0..%2)</source>
        <translation>%1: wait erwartet Millisekunden (0..%2)</translation>
    </message>
    <message>
        <source>%1: unknown command &apos;%2&apos; (send or wait)</source>
        <translation>%1: unbekannter Befehl &apos;%2&apos; (send oder wait)</translation>
    </message>
    <message>
        <source>not sent: the bus is not open</source>
        <translation>nicht gesendet: der Bus ist nicht offen</translation>
    </message>
    <message>
        <source>not sent: the bus refused the frame</source>
        <translation>nicht gesendet: der Bus hat den Frame abgelehnt</translation>
    </message>
    <message>
        <source>sent %1</source>
        <translation>gesendet: %1</translation>
    </message>
    <message>
        <source>sending %1 every %2 ms</source>
        <translation>sende %1 alle %2 ms</translation>
    </message>
    <message>
        <source>macro stopped at step %1 of %2</source>
        <translation>Makro bei Schritt %1 von %2 angehalten</translation>
    </message>
    <message numerus="yes">
        <source>macro done: %n step(s)</source>
        <translation>
            <numerusform>Makro fertig: %n Schritt</numerusform>
            <numerusform>Makro fertig: %n Schritte</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message numerus="yes">
        <source>every %1 ms: stopped after %n frame(s)</source>
        <translation>
            <numerusform>alle %1 ms: nach %n Frame gestoppt</numerusform>
            <numerusform>alle %1 ms: nach %n Frames gestoppt</numerusform>
        </translation>
    </message>
    <message>
        <source>macro stopped</source>
        <translation>Makro gestoppt</translation>
    </message>
    <message>
        <source>once</source>
        <translation>einmal</translation>
    </message>
    <message>
        <source>every %1 ms: started</source>
        <translation>alle %1 ms: gestartet</translation>
    </message>
    <message numerus="yes">
        <source>macro, %n step(s)</source>
        <translation>
            <numerusform>Makro, %n Schritt</numerusform>
            <numerusform>Makro, %n Schritte</numerusform>
        </translation>
    </message>
    <message>
        <source>step %1: %2</source>
        <translation>Schritt %1: %2</translation>
    </message>
</context>
<context>
    <name>db::widgets::GearBox</name>
    <message>
        <source>Electronic gear</source>
        <translation>Elektronisches Getriebe</translation>
    </message>
    <message>
        <source>Slave turns per master turn: numerator (negative: the other way)</source>
        <translation>Umdrehungen des Slaves je Umdrehung des Masters: Zähler (negativ: in die andere Richtung)</translation>
    </message>
    <message>
        <source>drive&apos;s own</source>
        <translation>die des Antriebs</translation>
    </message>
    <message>
        <source>Couple</source>
        <translation>Einkuppeln</translation>
    </message>
    <message>
        <source>MC_GearIn: follow the drive&apos;s master at this ratio</source>
        <translation>MC_GearIn: dem Master des Antriebs mit dieser Übersetzung folgen</translation>
    </message>
    <message>
        <source>Uncouple</source>
        <translation>Auskuppeln</translation>
    </message>
    <message>
        <source>MC_GearOut: the drive brakes the axis to a stop</source>
        <translation>MC_GearOut: der Antrieb bremst die Achse bis zum Stillstand</translation>
    </message>
    <message>
        <source>Ratio:</source>
        <translation>Übersetzung:</translation>
    </message>
    <message>
        <source>Acc.:</source>
        <translation>Beschl.:</translation>
    </message>
    <message>
        <source>Dec.:</source>
        <translation>Verz.:</translation>
    </message>
    <message>
        <source>Coupling at %1:%2 …</source>
        <translation>Kuppelt ein mit %1:%2 …</translation>
    </message>
    <message>
        <source>Uncoupling …</source>
        <translation>Kuppelt aus …</translation>
    </message>
    <message>
        <source>In gear at %1:%2</source>
        <translation>Eingekuppelt mit %1:%2</translation>
    </message>
    <message>
        <source>Uncoupled, at standstill</source>
        <translation>Ausgekuppelt, im Stillstand</translation>
    </message>
</context>
<context>
    <name>db::widgets::JogPanel</name>
    <message>
        <source>jog button released</source>
        <translation>Tipptaste losgelassen</translation>
    </message>
    <message>
        <source>the panel let go of the drive</source>
        <translation>das Bedienfeld hat den Antrieb freigegeben</translation>
    </message>
    <message>
        <source>units</source>
        <translation>Einh.</translation>
    </message>
    <message>
        <source>deadman watchdog: the GUI stopped refreshing for %1 ms</source>
        <translation>Totmann-Überwachung: die Oberfläche hat %1 ms lang nicht erneuert</translation>
    </message>
    <message>
        <source>Jog: %1</source>
        <translation>Tippen: %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>Gestoppt: %1</translation>
    </message>
    <message>
        <source>connection lost (%1); the drive may still be moving</source>
        <translation>Verbindung verloren (%1); der Antrieb kann noch in Bewegung sein</translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>Verbindung verloren: %1</translation>
    </message>
    <message>
        <source>focus left the jog panel</source>
        <translation>der Fokus hat das Tippfeld verlassen</translation>
    </message>
    <message>
        <source>Esc</source>
        <translation>Esc</translation>
    </message>
    <message>
        <source>jog key released</source>
        <translation>Tipptaste losgelassen</translation>
    </message>
    <message>
        <source>window deactivated</source>
        <translation>Fenster deaktiviert</translation>
    </message>
    <message>
        <source>jog panel hidden</source>
        <translation>Tippfeld ausgeblendet</translation>
    </message>
    <message>
        <source>Jog and step move in leases of %1 ms plus the braking distance: the drive stops by itself when the renewals stop.</source>
        <translation>Tippen und Schrittfahrt laufen in Freigaben von %1 ms plus Bremsweg: der Antrieb hält von selbst an, wenn die Erneuerungen ausbleiben.</translation>
    </message>
    <message>
        <source>No drive-side supervision on this connection.</source>
        <translation>Keine antriebsseitige Überwachung auf dieser Verbindung.</translation>
    </message>
    <message>
        <source>Active: %1.</source>
        <translation>Aktiv: %1.</translation>
    </message>
    <message>
        <source>On enable: %1.</source>
        <translation>Bei Freigabe: %1.</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Antrieb</translation>
    </message>
    <message>
        <source>Enable</source>
        <translation>Freigeben</translation>
    </message>
    <message>
        <source>Disable</source>
        <translation>Sperren</translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation>Störung quittieren</translation>
    </message>
    <message>
        <source>No drive</source>
        <translation>Kein Antrieb</translation>
    </message>
    <message>
        <source>Powered</source>
        <translation>Eingeschaltet</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>In Bewegung</translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation>Ziel erreicht</translation>
    </message>
    <message>
        <source>Referenced</source>
        <translation>Referenziert</translation>
    </message>
    <message>
        <source>Limit −</source>
        <translation>Grenze −</translation>
    </message>
    <message>
        <source>Limit +</source>
        <translation>Grenze +</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>Position:</translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation>Geschwindigkeit:</translation>
    </message>
    <message>
        <source>Jog (hold to run; keys ← → or − +)</source>
        <translation>Tippen (halten zum Fahren; Tasten ← → oder − +)</translation>
    </message>
    <message>
        <source>◀ Jog −</source>
        <translation>◀ Tippen −</translation>
    </message>
    <message>
        <source>Jog + ▶</source>
        <translation>Tippen + ▶</translation>
    </message>
    <message>
        <source>Step −</source>
        <translation>Schritt −</translation>
    </message>
    <message>
        <source>Step +</source>
        <translation>Schritt +</translation>
    </message>
    <message>
        <source>Accel.:</source>
        <translation>Beschl.:</translation>
    </message>
    <message>
        <source>Step:</source>
        <translation>Schritt:</translation>
    </message>
    <message>
        <source>Override:</source>
        <translation>Override:</translation>
    </message>
    <message>
        <source>Drive limits</source>
        <translation>Antriebsgrenzen</translation>
    </message>
    <message>
        <source>Not read yet</source>
        <translation>Noch nicht gelesen</translation>
    </message>
    <message>
        <source>Motion command</source>
        <translation>Bewegungsbefehl</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Reading the limits…</source>
        <translation>Lese die Grenzwerte…</translation>
    </message>
    <message>
        <source>Software limits (607Dh): the full 32-bit range</source>
        <translation>Software-Endlagen (607Dh): der volle 32-Bit-Bereich</translation>
    </message>
    <message>
        <source>Software limits (607Dh): %1 … %2 %3</source>
        <translation>Software-Endlagen (607Dh): %1 … %2 %3</translation>
    </message>
    <message>
        <source>Software limits (607Dh): none</source>
        <translation>Software-Endlagen (607Dh): keine</translation>
    </message>
    <message>
        <source>Max velocity: %1 %2</source>
        <translation>Max. Geschwindigkeit: %1 %2</translation>
    </message>
    <message>
        <source>Max velocity: not given by the drive</source>
        <translation>Max. Geschwindigkeit: vom Antrieb nicht angegeben</translation>
    </message>
    <message>
        <source>Max acceleration: %1 %2/s²</source>
        <translation>Max. Beschleunigung: %1 %2/s²</translation>
    </message>
    <message>
        <source>Max acceleration: not given by the drive</source>
        <translation>Max. Beschleunigung: vom Antrieb nicht angegeben</translation>
    </message>
    <message>
        <source>Position window: %1 %2</source>
        <translation>Positionsfenster: %1 %2</translation>
    </message>
    <message>
        <source>Stopped: %1. The axis is in ErrorStop now and takes no motion command until it is reset: click Reset.</source>
        <translation>Gestoppt: %1. Die Achse ist jetzt in ErrorStop und nimmt keinen Bewegungsbefehl an, bis sie zurückgesetzt ist: auf Zurücksetzen klicken.</translation>
    </message>
    <message>
        <source>The drive did not answer: its limits are not known yet.</source>
        <translation>Der Antrieb hat nicht geantwortet: seine Grenzen sind noch nicht bekannt.</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>MC_Reset: leave ErrorStop so that the axis takes commands again</source>
        <translation>MC_Reset: ErrorStop verlassen, damit die Achse wieder Befehle annimmt</translation>
    </message>
    <message>
        <source>Not responding</source>
        <translation>Antwortet nicht</translation>
    </message>
    <message>
        <source>ErrorStop: %1. The axis takes no motion command until Reset in the Motion dock.</source>
        <translation>ErrorStop: %1. Die Achse nimmt keinen Fahrbefehl an, bis Sie im Bereich Bewegung Zurücksetzen wählen.</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>Jog velocity</source>
        <translation>Tippgeschwindigkeit</translation>
    </message>
    <message>
        <source>Jog acceleration</source>
        <translation>Tippbeschleunigung</translation>
    </message>
    <message>
        <source>%1 %2 → %3 (the drive&apos;s maximum)</source>
        <translation>%1 %2 → %3 (Maximum des Antriebs)</translation>
    </message>
    <message>
        <source>Lowered to this drive&apos;s limits: %1</source>
        <translation>Auf die Grenzen dieses Antriebs gesenkt: %1</translation>
    </message>
    <message>
        <source>Disabled</source>
        <comment>PLCopen axis state</comment>
        <translation>Disabled (gesperrt)</translation>
    </message>
    <message>
        <source>Standstill</source>
        <comment>PLCopen axis state</comment>
        <translation>Standstill (Stillstand)</translation>
    </message>
    <message>
        <source>Discrete Motion</source>
        <comment>PLCopen axis state</comment>
        <translation>Discrete Motion (Positionierung)</translation>
    </message>
    <message>
        <source>Continuous Motion</source>
        <comment>PLCopen axis state</comment>
        <translation>Continuous Motion (Endlosbewegung)</translation>
    </message>
    <message>
        <source>Stopping</source>
        <comment>PLCopen axis state</comment>
        <translation>Stopping (Stoppen)</translation>
    </message>
    <message>
        <source>ErrorStop</source>
        <comment>PLCopen axis state</comment>
        <translation>ErrorStop (Fehlerstopp)</translation>
    </message>
    <message>
        <source>Homing</source>
        <comment>PLCopen axis state</comment>
        <translation>Homing (Referenzfahrt)</translation>
    </message>
    <message>
        <source>Synchronized Motion</source>
        <comment>PLCopen axis state</comment>
        <translation>Synchronized Motion (Synchronbetrieb)</translation>
    </message>
</context>
<context>
    <name>db::widgets::LogConsole</name>
    <message>
        <source>Connection events and warnings appear here.</source>
        <translation>Verbindungsereignisse und Warnungen erscheinen hier.</translation>
    </message>
    <message>
        <source>Copy All</source>
        <translation>Alles kopieren</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Changes and events</source>
        <translation>Änderungen und Ereignisse</translation>
    </message>
    <message>
        <source>Changes only</source>
        <translation>Nur Änderungen</translation>
    </message>
    <message>
        <source>Warnings and errors</source>
        <translation>Warnungen und Fehler</translation>
    </message>
    <message>
        <source>Events and protocol traffic</source>
        <translation>Ereignisse und Protokollverkehr</translation>
    </message>
    <message>
        <source>Everything, with debug lines</source>
        <translation>Alles, mit Debug-Zeilen</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Anzeigen</translation>
    </message>
</context>
<context>
    <name>db::widgets::LogPanel</name>
    <message>
        <source>Which lines the log shows. Protocol traffic and debug lines are kept only while they are shown.</source>
        <translation>Welche Zeilen das Protokoll zeigt. Protokollverkehr und Debug-Zeilen werden nur aufbewahrt, solange sie angezeigt werden.</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Save the lines shown to a text file</source>
        <translation>Die angezeigten Zeilen in eine Textdatei speichern</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>Anzeigen:</translation>
    </message>
    <message>
        <source>Save log</source>
        <translation>Protokoll speichern</translation>
    </message>
    <message>
        <source>Log files (*.log *.txt)</source>
        <translation>Protokolldateien (*.log *.txt)</translation>
    </message>
    <message>
        <source>Saved to %1</source>
        <translation>Gespeichert in %1</translation>
    </message>
</context>
<context>
    <name>db::widgets::LssPanel</name>
    <message>
        <source>All: configuration</source>
        <translation>Alle: Konfiguration</translation>
    </message>
    <message>
        <source>Every LSS slave to configuration mode (use it when only one is on the bus)</source>
        <translation>Alle LSS-Slaves in den Konfigurationsmodus (wenn nur einer am Bus ist)</translation>
    </message>
    <message>
        <source>All: waiting</source>
        <translation>Alle: Warten</translation>
    </message>
    <message>
        <source>Every LSS slave back to waiting (normal operation)</source>
        <translation>Alle LSS-Slaves zurück in den Wartemodus (Normalbetrieb)</translation>
    </message>
    <message>
        <source>Fastscan</source>
        <translation>Fastscan</translation>
    </message>
    <message>
        <source>Find one slave without a node id; it stays in configuration mode</source>
        <translation>Einen Slave ohne Knotennummer finden; er bleibt im Konfigurationsmodus</translation>
    </message>
    <message>
        <source>Inquire identity</source>
        <translation>Identität abfragen</translation>
    </message>
    <message>
        <source>Vendor, product, revision, serial and node id of the slave in configuration mode</source>
        <translation>Hersteller, Produkt, Revision, Seriennummer und Knotennummer des Slaves im Konfigurationsmodus</translation>
    </message>
    <message>
        <source>Assign node id</source>
        <translation>Knotennummer zuweisen</translation>
    </message>
    <message>
        <source>Give the slave in configuration mode this node id (applied at its next reset communication; Store keeps it)</source>
        <translation>Dem Slave im Konfigurationsmodus diese Knotennummer geben (gilt ab seinem nächsten Reset Communication; Speichern behält sie)</translation>
    </message>
    <message>
        <source>Assign bit rate</source>
        <translation>Bitrate zuweisen</translation>
    </message>
    <message>
        <source>Give the slave in configuration mode this bit rate (Store keeps it; it applies after a restart)</source>
        <translation>Dem Slave im Konfigurationsmodus diese Bitrate geben (Speichern behält sie; sie gilt nach einem Neustart)</translation>
    </message>
    <message>
        <source>Store</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>The slave in configuration mode keeps its node id and bit rate</source>
        <translation>Der Slave im Konfigurationsmodus behält seine Knotennummer und Bitrate</translation>
    </message>
    <message>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <source>Node id:</source>
        <translation>Knotennummer:</translation>
    </message>
    <message>
        <source>Bit rate:</source>
        <translation>Bitrate:</translation>
    </message>
    <message>
        <source>the bus is not open</source>
        <translation>der Bus ist nicht offen</translation>
    </message>
    <message>
        <source>switch mode not sent</source>
        <translation>Moduswechsel nicht gesendet</translation>
    </message>
    <message>
        <source>all slaves: configuration mode</source>
        <translation>alle Slaves: Konfigurationsmodus</translation>
    </message>
    <message>
        <source>all slaves: waiting</source>
        <translation>alle Slaves: Warten</translation>
    </message>
    <message>
        <source>fastscan…</source>
        <translation>Fastscan…</translation>
    </message>
    <message>
        <source>fastscan</source>
        <translation>Fastscan</translation>
    </message>
    <message>
        <source>found %1 (now in configuration mode)</source>
        <translation>%1 gefunden (jetzt im Konfigurationsmodus)</translation>
    </message>
    <message>
        <source>inquire: %1 (is one slave in configuration mode?)</source>
        <translation>Abfrage: %1 (ist genau ein Slave im Konfigurationsmodus?)</translation>
    </message>
    <message>
        <source>vendor</source>
        <translation>Hersteller</translation>
    </message>
    <message>
        <source>product</source>
        <translation>Produkt</translation>
    </message>
    <message>
        <source>revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>serial</source>
        <translation>Seriennummer</translation>
    </message>
    <message>
        <source>node id</source>
        <translation>Knotennummer</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>LSS node id</source>
        <translation>LSS-Knotennummer</translation>
    </message>
    <message>
        <source>assign node id %1</source>
        <translation>Knotennummer %1 zuweisen</translation>
    </message>
    <message>
        <source>LSS bit rate</source>
        <translation>LSS-Bitrate</translation>
    </message>
    <message>
        <source>assign %1 kbit/s</source>
        <translation>%1 kbit/s zuweisen</translation>
    </message>
    <message>
        <source>LSS node id and bit rate</source>
        <translation>LSS-Knotennummer und -Bitrate</translation>
    </message>
    <message>
        <source>store</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1: erledigt</translation>
    </message>
</context>
<context>
    <name>db::widgets::MorsePanel</name>
    <message>
        <source>Open video or CSV…</source>
        <translation>Video oder CSV öffnen…</translation>
    </message>
    <message>
        <source>Start camera</source>
        <translation>Kamera starten</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>No recording</source>
        <translation>Keine Aufzeichnung</translation>
    </message>
    <message>
        <source>LED frame</source>
        <translation>LED-Bild</translation>
    </message>
    <message>
        <source>IP: –</source>
        <translation>IP: –</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>MovingCap RefGo (refgo://IP)</source>
        <translation>MovingCap RefGo (refgo://IP)</translation>
    </message>
    <message>
        <source>CANopen over SLCAN (canopen+slcan://IP?node=50)</source>
        <translation>CANopen über SLCAN (canopen+slcan://IP?node=50)</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>brightness</source>
        <translation>Helligkeit</translation>
    </message>
    <message>
        <source>threshold</source>
        <translation>Schwelle</translation>
    </message>
    <message>
        <source>dit</source>
        <translation>dit</translation>
    </message>
    <message>
        <source>dah</source>
        <translation>dah</translation>
    </message>
    <message>
        <source>Open a video of the LED or a CSV of samples</source>
        <translation>Video der LED oder CSV mit Messwerten öffnen</translation>
    </message>
    <message>
        <source>Videos and CSV (*.mp4 *.mov *.avi *.mkv *.webm *.3gp *.csv *.txt);;All files (*)</source>
        <translation>Videos und CSV (*.mp4 *.mov *.avi *.mkv *.webm *.3gp *.csv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>No file reader in this build.</source>
        <translation>Kein Dateileser in dieser Version.</translation>
    </message>
    <message>
        <source>IP: %1  (%2)</source>
        <translation>IP: %1  (%2)</translation>
    </message>
    <message>
        <source>IP: %1  (partly read)</source>
        <translation>IP: %1  (teilweise gelesen)</translation>
    </message>
    <message>
        <source>Waiting for the blinking LED…</source>
        <translation>Warte auf die blinkende LED…</translation>
    </message>
    <message>
        <source>Open a video of the green STATUS LED (at least two message repetitions) or a CSV of samples, or start a camera.</source>
        <translation>Video der grünen STATUS-LED (mindestens zwei Wiederholungen der Meldung) oder CSV mit Messwerten öffnen oder eine Kamera starten.</translation>
    </message>
    <message>
        <source>Confident: %1 agreeing messages, unit %2 ms</source>
        <translation>Sicher: %1 übereinstimmende Meldungen, Einheit %2 ms</translation>
    </message>
    <message>
        <source>Decoding… </source>
        <translation>Dekodiere… </translation>
    </message>
    <message>
        <source>(CSV: no frame)</source>
        <translation>(CSV: kein Bild)</translation>
    </message>
    <message>
        <source>No camera input in this build</source>
        <translation>Kein Kameraeingang in dieser Version</translation>
    </message>
    <message>
        <source>No camera found (Qt Multimedia lists none)</source>
        <translation>Keine Kamera gefunden (Qt Multimedia listet keine)</translation>
    </message>
    <message>
        <source>Film the green STATUS LED: it is found automatically, or drag a rectangle around it on the frame</source>
        <translation>Die grüne STATUS-LED filmen: sie wird automatisch gefunden, oder ein Rechteck um sie im Bild ziehen</translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot;</source>
        <translation>Kamera „%1“</translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot; (stopped)</source>
        <translation>Kamera „%1“ (gestoppt)</translation>
    </message>
    <message>
        <source>Camera &quot;%1&quot;: %2</source>
        <translation>Kamera „%1“: %2</translation>
    </message>
</context>
<context>
    <name>db::widgets::MotionBlockBox</name>
    <message>
        <source>Motion block table</source>
        <translation>Fahrsatztabelle</translation>
    </message>
    <message>
        <source>Sequence</source>
        <translation>Folge</translation>
    </message>
    <message>
        <source>Run on through the blocks that follow this one</source>
        <translation>Die folgenden Fahrsätze anschließend fahren</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Wiederaufnehmen</translation>
    </message>
    <message>
        <source>Continue the interrupted block instead</source>
        <translation>Stattdessen den unterbrochenen Fahrsatz fortsetzen</translation>
    </message>
    <message>
        <source>Run block</source>
        <translation>Fahrsatz starten</translation>
    </message>
    <message>
        <source>Block:</source>
        <translation>Fahrsatz:</translation>
    </message>
    <message>
        <source>Block %1 running</source>
        <translation>Fahrsatz %1 läuft</translation>
    </message>
    <message>
        <source>Block %1 done</source>
        <translation>Fahrsatz %1 fertig</translation>
    </message>
</context>
<context>
    <name>db::widgets::MotionForm</name>
    <message>
        <source>idle</source>
        <translation>inaktiv</translation>
    </message>
    <message>
        <source>busy</source>
        <translation>belegt</translation>
    </message>
    <message>
        <source>active</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Optimised</source>
        <translation>Optimiert</translation>
    </message>
    <message>
        <source>Positive only</source>
        <translation>Nur positiv</translation>
    </message>
    <message>
        <source>Negative only</source>
        <translation>Nur negativ</translation>
    </message>
    <message>
        <source>Keep direction</source>
        <translation>Richtung beibehalten</translation>
    </message>
    <message>
        <source> ‰ rated</source>
        <translation> ‰ Nennwert</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>Befehl:</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Ziel:</translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation>Geschwindigkeit:</translation>
    </message>
    <message>
        <source>Jerk:</source>
        <translation>Ruck:</translation>
    </message>
    <message>
        <source>Accel.:</source>
        <translation>Beschl.:</translation>
    </message>
    <message>
        <source>Decel.:</source>
        <translation>Verz.:</translation>
    </message>
    <message>
        <source>Direction:</source>
        <translation>Richtung:</translation>
    </message>
    <message>
        <source>Homing:</source>
        <translation>Referenzfahrt:</translation>
    </message>
    <message>
        <source>Offset:</source>
        <translation>Offset:</translation>
    </message>
    <message>
        <source>Torque:</source>
        <translation>Drehmoment:</translation>
    </message>
    <message>
        <source>Execute</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>Halt</source>
        <translation>Halt</translation>
    </message>
    <message>
        <source>MC_Halt: brake with the deceleration; a new command may follow at once</source>
        <translation>MC_Halt: mit der Verzögerung bremsen; ein neuer Befehl darf sofort folgen</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>MC_Stop: brake with the deceleration; other commands are refused until standstill</source>
        <translation>MC_Stop: mit der Verzögerung bremsen; andere Befehle werden bis zum Stillstand abgelehnt</translation>
    </message>
    <message>
        <source>No command yet</source>
        <translation>Noch kein Befehl</translation>
    </message>
    <message>
        <source>No drive</source>
        <translation>Kein Antrieb</translation>
    </message>
    <message>
        <source>35: set current position as zero</source>
        <translation>35: aktuelle Position als Null setzen</translation>
    </message>
    <message>
        <source>This drive has no torque mode: the command will be refused.</source>
        <translation>Dieser Antrieb hat keinen Drehmomentmodus: der Befehl wird abgelehnt.</translation>
    </message>
    <message>
        <source>The drive has no jerk object; the jerk field only satisfies the command rules.</source>
        <translation>Der Antrieb hat kein Ruck-Objekt; das Ruck-Feld dient nur den Befehlsregeln.</translation>
    </message>
    <message>
        <source> (target %1)</source>
        <translation> (Ziel %1)</translation>
    </message>
    <message>
        <source>velocity limited to the maximum</source>
        <translation>Geschwindigkeit auf das Maximum begrenzt</translation>
    </message>
    <message>
        <source>override clamped at the maximum velocity</source>
        <translation>Override auf die Maximalgeschwindigkeit begrenzt</translation>
    </message>
    <message>
        <source>acceleration or jerk limited</source>
        <translation>Beschleunigung oder Ruck begrenzt</translation>
    </message>
    <message>
        <source>%1 not started: %2. Correct the input; the axis is unchanged.</source>
        <translation>%1 nicht gestartet: %2. Eingabe korrigieren; die Achse ist unverändert.</translation>
    </message>
    <message>
        <source>At most %1%2: %3</source>
        <translation>Höchstens %1%2: %3</translation>
    </message>
    <message>
        <source>%1 %2 → %3%4: %5</source>
        <translation>%1 %2 → %3%4: %5</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>the drive&apos;s maximum velocity</source>
        <translation>die Höchstgeschwindigkeit des Antriebs</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>the drive&apos;s maximum acceleration</source>
        <translation>die Höchstbeschleunigung des Antriebs</translation>
    </message>
    <message>
        <source>Deceleration</source>
        <translation>Verzögerung</translation>
    </message>
    <message>
        <source>Jerk</source>
        <translation>Ruck</translation>
    </message>
    <message>
        <source>the drive&apos;s maximum jerk</source>
        <translation>der höchste Ruck des Antriebs</translation>
    </message>
    <message>
        <source>Lowered to this drive&apos;s limits: %1</source>
        <translation>Auf die Grenzen dieses Antriebs gesenkt: %1</translation>
    </message>
    <message>
        <source>MC_MoveVelocity in leases</source>
        <translation>MC_MoveVelocity in befristeten Abschnitten</translation>
    </message>
    <message>
        <source>axis not referenced: positions count from the drive&apos;s present zero</source>
        <translation>Achse nicht referenziert: Positionen zählen vom jetzigen Nullpunkt des Antriebs</translation>
    </message>
    <message>
        <source>Direction of travel: used by MC_MoveAbsolute on an endless axis</source>
        <translation>Bewegungsrichtung: wirkt bei MC_MoveAbsolute auf einer Endlosachse</translation>
    </message>
</context>
<context>
    <name>db::widgets::NetworkView</name>
    <message>
        <source>SYNC producer</source>
        <translation>SYNC-Erzeuger</translation>
    </message>
    <message>
        <source>Send SYNC (080h) on this bus every period; synchronous PDOs follow it</source>
        <translation>SYNC (080h) auf diesem Bus in jeder Periode senden; synchrone PDOs folgen ihm</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>SYNC period (communication cycle)</source>
        <translation>SYNC-Periode (Kommunikationszyklus)</translation>
    </message>
    <message>
        <source>PDO mapping</source>
        <translation>PDO-Mapping</translation>
    </message>
    <message>
        <source>LSS</source>
        <translation>LSS</translation>
    </message>
    <message>
        <source>CANopen network on %1</source>
        <translation>CANopen-Netz an %1</translation>
    </message>
    <message>
        <source>No CANopen connection: connect to a CANopen node to see its network.</source>
        <translation>Keine CANopen-Verbindung: verbinden Sie sich mit einem CANopen-Knoten, um sein Netz zu sehen.</translation>
    </message>
</context>
<context>
    <name>db::widgets::Nm17xAddressingDialog</name>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Address the displays along the line</source>
        <translation>Anzeigen entlang der Linie adressieren</translation>
    </message>
    <message>
        <source>until none answers</source>
        <translation>bis keine mehr antwortet</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Every display on the bus will show the node id offered. The display whose shaft is turned (or whose key is pressed) takes it; then the next id is offered.</source>
        <translation>Jede Anzeige am Bus zeigt die angebotene Knotennummer. Die Anzeige, deren Welle gedreht (oder deren Taste gedrückt) wird, übernimmt sie; dann wird die nächste angeboten.</translation>
    </message>
    <message>
        <source>First node id:</source>
        <translation>Erste Knotennummer:</translation>
    </message>
    <message>
        <source>Number of displays:</source>
        <translation>Anzahl Anzeigen:</translation>
    </message>
    <message>
        <source>Time per display:</source>
        <translation>Zeit je Anzeige:</translation>
    </message>
    <message>
        <source>Addressing could not start.</source>
        <translation>Die Adressierung konnte nicht beginnen.</translation>
    </message>
    <message>
        <source>cancelled while node %1 was offered</source>
        <translation>abgebrochen, während Knoten %1 angeboten war</translation>
    </message>
    <message>
        <source>Turn the shaft (or press a key) of the display that should become node %1.</source>
        <translation>Drehen Sie die Welle (oder drücken Sie eine Taste) der Anzeige, die Knoten %1 werden soll.</translation>
    </message>
    <message>
        <source>node %1: taken by a display</source>
        <translation>Knoten %1: von einer Anzeige übernommen</translation>
    </message>
    <message>
        <source>node %1: %2</source>
        <translation>Knoten %1: %2</translation>
    </message>
    <message>
        <source>No display took a node id.</source>
        <translation>Keine Anzeige hat eine Knotennummer übernommen.</translation>
    </message>
    <message numerus="yes">
        <source>%n display(s) addressed: node %1. All nodes were reset so that the new ids are in effect; find the displays again.</source>
        <translation>
            <numerusform>%n Anzeige adressiert: Knoten %1. Alle Knoten wurden zurückgesetzt, damit die neuen Nummern gelten; suchen Sie die Anzeigen erneut.</numerusform>
            <numerusform>%n Anzeigen adressiert: Knoten %1. Alle Knoten wurden zurückgesetzt, damit die neuen Nummern gelten; suchen Sie die Anzeigen erneut.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 s left for node %2</source>
        <translation>noch %1 s für Knoten %2</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>%v of %m</source>
        <translation>%v von %m</translation>
    </message>
</context>
<context>
    <name>db::widgets::Nm17xLineModel</name>
    <message>
        <source> (right)</source>
        <translation> (rechts)</translation>
    </message>
    <message>
        <source> (left)</source>
        <translation> (links)</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Variant</source>
        <translation>Variante</translation>
    </message>
    <message>
        <source>Serial number</source>
        <translation>Seriennummer</translation>
    </message>
    <message>
        <source>Setpoint</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Correction</source>
        <translation>Korrektur</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>reading the error word 204Eh:02: %1</source>
        <translation>Lesen des Fehlerworts 204Eh:02: %1</translation>
    </message>
    <message>
        <source>error (its code could not be read)</source>
        <translation>Fehler (Code nicht lesbar)</translation>
    </message>
    <message>
        <source>error (reading its code…)</source>
        <translation>Fehler (Code wird gelesen…)</translation>
    </message>
    <message>
        <source>error (code unknown)</source>
        <translation>Fehler (Code unbekannt)</translation>
    </message>
</context>
<context>
    <name>db::widgets::Nm17xLinePanel</name>
    <message>
        <source>standard</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>with release</source>
        <translation>mit Freigabe</translation>
    </message>
    <message>
        <source>direct (no loop)</source>
        <translation>direkt (ohne Schleifenfahrt)</translation>
    </message>
    <message>
        <source>plunge cut</source>
        <translation>Einsägen</translation>
    </message>
    <message>
        <source>plunge cut with release</source>
        <translation>Einsägen mit Freigabe</translation>
    </message>
    <message>
        <source>Find displays</source>
        <translation>Anzeigen suchen</translation>
    </message>
    <message>
        <source>Send setpoint</source>
        <translation>Sollwert senden</translation>
    </message>
    <message>
        <source>Jog left</source>
        <translation>Links tippen</translation>
    </message>
    <message>
        <source>Jog right</source>
        <translation>Rechts tippen</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Show node ids</source>
        <translation>Knoten-IDs anzeigen</translation>
    </message>
    <message>
        <source>Preset all</source>
        <translation>Alle voreinstellen</translation>
    </message>
    <message>
        <source>Start group</source>
        <translation>Gruppe starten</translation>
    </message>
    <message>
        <source>Stop all</source>
        <translation>Alle stoppen</translation>
    </message>
    <message>
        <source>Unit:</source>
        <translation>Einheit:</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Tempo:</translation>
    </message>
    <message>
        <source>looking for displays ...</source>
        <translation>suche Anzeigen ...</translation>
    </message>
    <message numerus="yes">
        <source>%n display(s) found</source>
        <translation>
            <numerusform>%n Anzeige gefunden</numerusform>
            <numerusform>%n Anzeigen gefunden</numerusform>
        </translation>
    </message>
    <message>
        <source>node %1: setpoint %2 sent</source>
        <translation>Knoten %1: Sollwert %2 gesendet</translation>
    </message>
    <message>
        <source>node %1: jogging %2</source>
        <translation>Knoten %1: tippt %2</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>node %1: stop sent</source>
        <translation>Knoten %1: Stopp gesendet</translation>
    </message>
    <message>
        <source>every display shows %1</source>
        <translation>jede Anzeige zeigt %1</translation>
    </message>
    <message>
        <source>inch</source>
        <translation>Zoll</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>every display shows its node id</source>
        <translation>jede Anzeige zeigt ihre Knoten-ID</translation>
    </message>
    <message>
        <source>every display preset to %1</source>
        <translation>jede Anzeige auf %1 voreingestellt</translation>
    </message>
    <message>
        <source>group %1 started</source>
        <translation>Gruppe %1 gestartet</translation>
    </message>
    <message>
        <source>every display stopped</source>
        <translation>jede Anzeige gestoppt</translation>
    </message>
    <message>
        <source>Address line…</source>
        <translation>Linie adressieren…</translation>
    </message>
    <message>
        <source>Give the displays their node ids one after the other: the display whose shaft is turned takes the id offered</source>
        <translation>Den Anzeigen nacheinander ihre Knotennummern geben: die Anzeige, deren Welle gedreht wird, übernimmt die angebotene</translation>
    </message>
    <message>
        <source>Addressing finished; the displays restart with their new node ids.</source>
        <translation>Adressierung beendet; die Anzeigen starten mit ihren neuen Knotennummern neu.</translation>
    </message>
    <message>
        <source>Scan 125/250 kbit/s</source>
        <translation>Suche bei 125/250 kbit/s</translation>
    </message>
    <message>
        <source>Look for displays at 125 and 250 kbit/s: they are delivered at 125 kbit/s, but their bit-rate setting defaults to 250</source>
        <translation>Anzeigen bei 125 und 250 kbit/s suchen: Sie werden mit 125 kbit/s ausgeliefert, ihre Bitrateneinstellung steht aber ab Werk auf 250</translation>
    </message>
    <message>
        <source>Selected display: modes and settings</source>
        <translation>Gewählte Anzeige: Betriebsarten und Einstellungen</translation>
    </message>
    <message>
        <source>looking for displays at 125 and 250 kbit/s ...</source>
        <translation>suche Anzeigen bei 125 und 250 kbit/s …</translation>
    </message>
    <message>
        <source>%1 kbit/s: no display</source>
        <translation>%1 kbit/s: keine Anzeige</translation>
    </message>
    <message>
        <source>%1 kbit/s: node %2</source>
        <translation>%1 kbit/s: Knoten %2</translation>
    </message>
    <message>
        <source>The CAN bus %1 is not open (yet).</source>
        <translation>Der CAN-Bus %1 ist (noch) nicht offen.</translation>
    </message>
</context>
<context>
    <name>db::widgets::Nm17xSettingsBox</name>
    <message>
        <source>Oscillate</source>
        <translation>Oszillieren</translation>
    </message>
    <message>
        <source>Stop oscillating</source>
        <translation>Oszillieren beenden</translation>
    </message>
    <message>
        <source>Set scaling</source>
        <translation>Skalierung setzen</translation>
    </message>
    <message>
        <source>Set filter</source>
        <translation>Filter setzen</translation>
    </message>
    <message>
        <source>Dynamic pre-shutdown</source>
        <translation>Dynamische Vorabschaltung</translation>
    </message>
    <message>
        <source> mm/rev</source>
        <translation> mm/U</translation>
    </message>
    <message>
        <source> steps/rev</source>
        <translation> Schritte/U</translation>
    </message>
    <message>
        <source> steps</source>
        <translation> Schritte</translation>
    </message>
    <message>
        <source> jumps</source>
        <translation> Sprünge</translation>
    </message>
    <message>
        <source>What the external inputs F and G do</source>
        <translation>Was die externen Eingänge F und G tun</translation>
    </message>
    <message>
        <source>How the device keys drive the motor</source>
        <translation>Wie die Gerätetasten den Motor fahren</translation>
    </message>
    <message>
        <source>Position jumps larger than this are filtered out</source>
        <translation>Positionssprünge, die größer sind, werden herausgefiltert</translation>
    </message>
    <message>
        <source>Consecutive jumps filtered before one is taken as real</source>
        <translation>Aufeinanderfolgende Sprünge, die gefiltert werden, bevor einer als echt gilt</translation>
    </message>
    <message>
        <source>After each positioning, half the distance by which the target was missed moves the switch-off point</source>
        <translation>Nach jeder Positionierung verschiebt die halbe Abweichung vom Ziel den Abschaltpunkt</translation>
    </message>
    <message>
        <source>Inputs F/G:</source>
        <translation>Eingänge F/G:</translation>
    </message>
    <message>
        <source>Keys:</source>
        <translation>Tasten:</translation>
    </message>
    <message>
        <source>Pitch:</source>
        <translation>Steigung:</translation>
    </message>
    <message>
        <source>Jump filter:</source>
        <translation>Sprungfilter:</translation>
    </message>
    <message>
        <source>switch-off point %1</source>
        <translation>Abschaltpunkt %1</translation>
    </message>
    <message>
        <source>%1 = %2 mm/rev</source>
        <translation>%1 = %2 mm/U</translation>
    </message>
    <message>
        <source>node %1: %2</source>
        <translation>Knoten %1: %2</translation>
    </message>
    <message>
        <source>inputs F/G: %1</source>
        <translation>Eingänge F/G: %1</translation>
    </message>
    <message>
        <source>keys: %1</source>
        <translation>Tasten: %1</translation>
    </message>
    <message>
        <source>node %1: oscillating between D1 and D2</source>
        <translation>Knoten %1: oszilliert zwischen D1 und D2</translation>
    </message>
    <message>
        <source>node %1: oscillation stopped</source>
        <translation>Knoten %1: Oszillieren beendet</translation>
    </message>
    <message>
        <source>scaling %1 (%2 mm/rev, %3 steps/rev)</source>
        <translation>Skalierung %1 (%2 mm/U, %3 Schritte/U)</translation>
    </message>
    <message>
        <source>jump filter %1 steps</source>
        <translation>Sprungfilter %1 Schritte</translation>
    </message>
    <message>
        <source>jump filter count %1</source>
        <translation>Sprungfilter-Anzahl %1</translation>
    </message>
    <message>
        <source>dynamic pre-shutdown on</source>
        <translation>dynamische Vorabschaltung ein</translation>
    </message>
    <message>
        <source>dynamic pre-shutdown off</source>
        <translation>dynamische Vorabschaltung aus</translation>
    </message>
    <message>
        <source>Enter the spindle pitch first: the display&apos;s scaling could not be read.</source>
        <translation>Zuerst die Spindelsteigung eingeben: die Skalierung der Anzeige konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>Enter the jump filter&apos;s width and count first: the display&apos;s filter could not be read.</source>
        <translation>Zuerst Breite und Anzahl des Sprungfilters eingeben: der Filter der Anzeige konnte nicht gelesen werden.</translation>
    </message>
</context>
<context>
    <name>db::widgets::NodeList</name>
    <message>
        <source>All nodes</source>
        <translation>Alle Knoten</translation>
    </message>
    <message>
        <source>Send NMT commands to every node (node id 0)</source>
        <translation>NMT-Befehle an alle Knoten senden (Knoten-ID 0)</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>NMT start: operational</source>
        <translation>NMT Start: operational</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>NMT stop: stopped</source>
        <translation>NMT Stopp: gestoppt</translation>
    </message>
    <message>
        <source>Pre-op</source>
        <translation>Pre-op</translation>
    </message>
    <message>
        <source>NMT enter pre-operational</source>
        <translation>NMT nach pre-operational</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>NMT reset node (application)</source>
        <translation>NMT Reset Node (Anwendung)</translation>
    </message>
    <message>
        <source>Reset comm</source>
        <translation>Reset Komm.</translation>
    </message>
    <message>
        <source>NMT reset communication</source>
        <translation>NMT Reset Communication</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>Ask node ids 1..127 by SDO and list every node that answers, with its name (1008h) and identity (1018h)</source>
        <translation>Knotennummern 1..127 per SDO fragen und jeden antwortenden Knoten mit Namen (1008h) und Identität (1018h) auflisten</translation>
    </message>
    <message>
        <source>vendor %1, product %2, revision %3, serial %4</source>
        <translation>Hersteller %1, Produkt %2, Revision %3, Seriennummer %4</translation>
    </message>
    <message>
        <source>Scanning…</source>
        <translation>Suche…</translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation>alle Knoten</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>%1 sent to all nodes</source>
        <translation>%1 an alle Knoten gesendet</translation>
    </message>
    <message>
        <source>%1 sent to node %2: waiting for its heartbeat</source>
        <translation>%1 an Knoten %2 gesendet: warte auf seinen Heartbeat</translation>
    </message>
    <message>
        <source>%1 to node %2: %3</source>
        <translation>%1 an Knoten %2: %3</translation>
    </message>
    <message>
        <source>%1 sent to node %2; %3</source>
        <translation>%1 an Knoten %2 gesendet; %3</translation>
    </message>
    <message>
        <source>%1: node %2 followed</source>
        <translation>%1: Knoten %2 ist gefolgt</translation>
    </message>
</context>
<context>
    <name>db::widgets::NodeListModel</name>
    <message>
        <source>lost (was %1)</source>
        <translation>verloren (war %1)</translation>
    </message>
    <message>
        <source>unknown (sent %1)</source>
        <translation>unbekannt (gesendet %1)</translation>
    </message>
    <message>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <source>%1 s ago</source>
        <translation>vor %1 s</translation>
    </message>
    <message>
        <source>The node of this connection</source>
        <translation>Der Knoten dieser Verbindung</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation>NMT-Zustand</translation>
    </message>
    <message>
        <source>Heartbeat</source>
        <translation>Heartbeat</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>Heartbeat consumer time: silence longer than this after a heartbeat shows the node as lost (double-click to change; 0 = not watched)</source>
        <translation>Heartbeat-Überwachungszeit: bleibt der Knoten nach einem Heartbeat länger still, gilt er als verloren (Doppelklick zum Ändern; 0 = nicht überwacht)</translation>
    </message>
    <message>
        <source>Consumer</source>
        <translation>Überwachung</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
</context>
<context>
    <name>db::widgets::ObjectAccessBox</name>
    <message>
        <source>He&amp;x</source>
        <translation>He&amp;x</translation>
    </message>
    <message>
        <source>&amp;Read</source>
        <translation>&amp;Lesen</translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation>&amp;Schreiben</translation>
    </message>
    <message>
        <source>auto (integer)</source>
        <translation>auto (Ganzzahl)</translation>
    </message>
    <message>
        <source>Data type for objects the device description does not know</source>
        <translation>Datentyp für Objekte, die die Gerätebeschreibung nicht kennt</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Object:</source>
        <translation>Objekt:</translation>
    </message>
    <message>
        <source>Value:</source>
        <translation>Wert:</translation>
    </message>
    <message>
        <source>&lt;br&gt;%1, %2</source>
        <translation>&lt;br&gt;%1, %2</translation>
    </message>
    <message>
        <source>, unit %1</source>
        <translation>, Einheit %1</translation>
    </message>
    <message>
        <source>%1 is not in the device description; it is read as an integer, or as the type you pick.</source>
        <translation>%1 steht nicht in der Gerätebeschreibung; es wird als Ganzzahl gelesen oder mit dem gewählten Typ.</translation>
    </message>
    <message>
        <source>This object is read-only</source>
        <translation>Dieses Objekt ist nur lesbar</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>%1 %2 is read-only</source>
        <translation>%1 %2 ist nur lesbar</translation>
    </message>
    <message>
        <source>read %1</source>
        <translation>%1 gelesen</translation>
    </message>
    <message>
        <source>written %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>Enter an object address, e.g. %1</source>
        <translation>Objektadresse eingeben, z. B. %1</translation>
    </message>
</context>
<context>
    <name>db::widgets::OdBitFieldView</name>
    <message>
        <source>Select an object to see its details.</source>
        <translation>Ein Objekt auswählen, um seine Details zu sehen.</translation>
    </message>
    <message>
        <source>, storable</source>
        <translation>, speicherbar</translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation>Einschalten</translation>
    </message>
    <message>
        <source>Enable voltage</source>
        <translation>Spannung freigeben</translation>
    </message>
    <message>
        <source>Quick stop</source>
        <translation>Schnellhalt</translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation>Betrieb freigeben</translation>
    </message>
    <message>
        <source>Operation mode specific</source>
        <translation>Betriebsartabhängig</translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation>Störung quittieren</translation>
    </message>
    <message>
        <source>Halt</source>
        <translation>Halt</translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation>Einschaltbereit</translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation>Eingeschaltet</translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation>Betrieb freigegeben</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <source>Voltage enabled</source>
        <translation>Spannung freigegeben</translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation>Einschaltsperre</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Remote</source>
        <translation>Fernsteuerung</translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation>Ziel erreicht</translation>
    </message>
    <message>
        <source>Internal limit active</source>
        <translation>Interne Begrenzung aktiv</translation>
    </message>
    <message>
        <source>Negative limit switch</source>
        <translation>Negativer Endschalter</translation>
    </message>
    <message>
        <source>Positive limit switch</source>
        <translation>Positiver Endschalter</translation>
    </message>
    <message>
        <source>Home switch</source>
        <translation>Referenzschalter</translation>
    </message>
    <message>
        <source>Interlock</source>
        <translation>Verriegelung</translation>
    </message>
</context>
<context>
    <name>db::widgets::OdEditor</name>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>He&amp;x</source>
        <translation>He&amp;x</translation>
    </message>
    <message>
        <source>Filter by index, name or value (e.g. 6041, velocity)</source>
        <translation>Nach Index, Name oder Wert filtern (z. B. 6041, velocity)</translation>
    </message>
    <message>
        <source>Live refresh of the rows on screen</source>
        <translation>Sichtbare Zeilen laufend aktualisieren</translation>
    </message>
    <message>
        <source>Read all</source>
        <translation>Alles lesen</translation>
    </message>
    <message>
        <source>Read every object of the device once</source>
        <translation>Jedes Objekt des Geräts einmal lesen</translation>
    </message>
    <message>
        <source>By index…</source>
        <translation>Nach Index…</translation>
    </message>
    <message>
        <source>Read or write an object the device description does not list</source>
        <translation>Ein Objekt lesen oder schreiben, das die Gerätebeschreibung nicht enthält</translation>
    </message>
    <message>
        <source>Refresh:</source>
        <translation>Aktualisierung:</translation>
    </message>
    <message>
        <source>%1 not written: %2</source>
        <translation>%1 nicht geschrieben: %2</translation>
    </message>
    <message>
        <source>No device</source>
        <translation>Kein Gerät</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>Writing %1 %2…</source>
        <translation>Schreibe %1 %2…</translation>
    </message>
    <message>
        <source>%1 %2 written</source>
        <translation>%1 %2 geschrieben</translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message numerus="yes">
        <source>%n object(s)</source>
        <translation>
            <numerusform>%n Objekt</numerusform>
            <numerusform>%n Objekte</numerusform>
        </translation>
    </message>
    <message>
        <source>filter: %1</source>
        <translation>Filter: %1</translation>
    </message>
    <message>
        <source>Read/Write by Index</source>
        <translation>Lesen/Schreiben nach Index</translation>
    </message>
    <message>
        <source>Objects that the device description does not list are added to the tree once read or written.</source>
        <translation>Objekte, die die Gerätebeschreibung nicht enthält, werden nach dem Lesen oder Schreiben in den Baum aufgenommen.</translation>
    </message>
    <message>
        <source>%1 cannot be used: %2</source>
        <translation>%1 ist nicht verwendbar: %2</translation>
    </message>
    <message>
        <source>Description: %1</source>
        <translation>Beschreibung: %1</translation>
    </message>
    <message>
        <source>Write to RAM</source>
        <translation>Ins RAM schreiben</translation>
    </message>
    <message>
        <source>Edits change the working value only: lost at power-off, the EEPROM is not written. Off: edits are stored permanently in the data set.</source>
        <translation>Änderungen gelten nur für den Arbeitswert: nach dem Ausschalten verloren, das EEPROM wird nicht beschrieben. Aus: Änderungen werden dauerhaft im Datensatz gespeichert.</translation>
    </message>
    <message>
        <source>to RAM (%1, lost at power-off)</source>
        <translation>ins RAM (%1, nach dem Ausschalten verloren)</translation>
    </message>
    <message>
        <source>%v of %m</source>
        <translation>%v von %m</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop reading every object (values read so far stay)</source>
        <translation>Das Lesen aller Objekte abbrechen (bereits gelesene Werte bleiben)</translation>
    </message>
</context>
<context>
    <name>db::widgets::OdEditorDelegate</name>
    <message>
        <source>0 (false)</source>
        <translation>0 (falsch)</translation>
    </message>
    <message>
        <source>1 (true)</source>
        <translation>1 (wahr)</translation>
    </message>
</context>
<context>
    <name>db::widgets::OdEditorModel</name>
    <message>
        <source>Communication (1000h–1FFFh)</source>
        <translation>Kommunikation (1000h–1FFFh)</translation>
    </message>
    <message>
        <source>Manufacturer (2000h–5FFFh)</source>
        <translation>Herstellerspezifisch (2000h–5FFFh)</translation>
    </message>
    <message>
        <source>Device profile (6000h–9FFFh)</source>
        <translation>Geräteprofil (6000h–9FFFh)</translation>
    </message>
    <message>
        <source>Other</source>
        <translation>Sonstige</translation>
    </message>
    <message>
        <source>Not in the description</source>
        <translation>Nicht in der Beschreibung</translation>
    </message>
    <message>
        <source>Index:Sub</source>
        <translation>Index:Sub</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Min … Max</source>
        <translation>Min … Max</translation>
    </message>
    <message>
        <source>PDO</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>writing %1…</source>
        <translation>Schreibe %1…</translation>
    </message>
    <message>
        <source>written</source>
        <translation>geschrieben</translation>
    </message>
    <message>
        <source>read-only</source>
        <translation>nur lesbar</translation>
    </message>
    <message>
        <source>(write-only)</source>
        <translation>(nur schreibbar)</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>%1 is %2 and cannot be written</source>
        <translation>%1 ist %2 und kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>enter a value</source>
        <translation>einen Wert eingeben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>DS %1</source>
        <translation>DS %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Differs from the default %1</source>
        <translation>Weicht vom Standardwert %1 ab</translation>
    </message>
    <message>
        <source>Read before the connection ended; may be out of date</source>
        <translation>Gelesen, bevor die Verbindung endete; möglicherweise veraltet</translation>
    </message>
    <message>
        <source>English: %1</source>
        <translation>Englisch: %1</translation>
    </message>
</context>
<context>
    <name>db::widgets::ParamCompareModel</name>
    <message>
        <source>Not restorable: the file has no value, or the object is read-only or unknown</source>
        <translation>Nicht wiederherstellbar: die Datei hat keinen Wert, oder das Objekt ist nur lesbar oder unbekannt</translation>
    </message>
    <message>
        <source>Index:Sub</source>
        <translation>Index:Sub</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>Standardwerte</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
</context>
<context>
    <name>db::widgets::ParamCompareReport</name>
    <message>
        <source>Restore Report</source>
        <translation>Wiederherstellungsbericht</translation>
    </message>
    <message>
        <source>Restore Report — Incomplete</source>
        <translation>Wiederherstellungsbericht — unvollständig</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 written&lt;/b&gt; (%2 verified by reading back), &lt;b&gt;%3 failed&lt;/b&gt;, %4 mismatched, %5 skipped.</source>
        <translation>&lt;b&gt;%1 geschrieben&lt;/b&gt; (%2 durch Rücklesen geprüft), &lt;b&gt;%3 fehlgeschlagen&lt;/b&gt;, %4 abweichend, %5 übersprungen.</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>Gestoppt: %1</translation>
    </message>
    <message>
        <source>Stored permanently (1010h).</source>
        <translation>Dauerhaft gespeichert (1010h).</translation>
    </message>
    <message>
        <source>Not stored permanently: %1</source>
        <translation>Nicht dauerhaft gespeichert: %1</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Index:Sub</source>
        <translation>Index:Sub</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Reason</source>
        <translation>Grund</translation>
    </message>
    <message>
        <source>&amp;Copy Report</source>
        <translation>Bericht &amp;kopieren</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
</context>
<context>
    <name>db::widgets::ParamCompareView</name>
    <message>
        <source>Only &amp;differences</source>
        <translation>Nur &amp;Unterschiede</translation>
    </message>
    <message>
        <source>Status includes d&amp;efaults</source>
        <translation>Status berücksichtigt &amp;Standardwerte</translation>
    </message>
    <message>
        <source>He&amp;x</source>
        <translation>He&amp;x</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>&amp;Load Set…</source>
        <translation>Satz &amp;laden…</translation>
    </message>
    <message>
        <source>Re-read &amp;Device</source>
        <translation>Gerät &amp;neu lesen</translation>
    </message>
    <message>
        <source>Select Differences</source>
        <translation>Unterschiede auswählen</translation>
    </message>
    <message>
        <source>Select None</source>
        <translation>Nichts auswählen</translation>
    </message>
    <message>
        <source>Store permanently afterwards (1010h)</source>
        <translation>Anschließend dauerhaft speichern (1010h)</translation>
    </message>
    <message>
        <source>&amp;Restore Selected…</source>
        <translation>Ausgewählte &amp;wiederherstellen…</translation>
    </message>
    <message>
        <source>Off: the status compares device and file only. On: a row also counts as changed or missing when the defaults differ.</source>
        <translation>Aus: der Status vergleicht nur Gerät und Datei. Ein: eine Zeile gilt auch als geändert oder fehlend, wenn die Standardwerte abweichen.</translation>
    </message>
    <message>
        <source>After every row was written and verified, write &quot;save&quot; to 1010h so the values survive a power cycle</source>
        <translation>Nachdem jede Zeile geschrieben und geprüft ist, „save“ nach 1010h schreiben, damit die Werte einen Neustart überstehen</translation>
    </message>
    <message>
        <source>No parameter set loaded. &lt;i&gt;Load Set…&lt;/i&gt; reads a file made by &lt;i&gt;Back Up…&lt;/i&gt; or &lt;code&gt;drivebench-cli backup&lt;/code&gt;; nothing is written to the device until you restore.</source>
        <translation>Kein Parametersatz geladen. &lt;i&gt;Satz laden…&lt;/i&gt; liest eine mit &lt;i&gt;Sichern…&lt;/i&gt; oder &lt;code&gt;drivebench-cli backup&lt;/code&gt; erstellte Datei; auf das Gerät wird erst beim Wiederherstellen geschrieben.</translation>
    </message>
    <message>
        <source>Load Parameter Set</source>
        <translation>Parametersatz laden</translation>
    </message>
    <message>
        <source>Parameter sets (*.dbp *.txt);;All files (*)</source>
        <translation>Parametersätze (*.dbp *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Cannot load %1: %2</source>
        <translation>%1 kann nicht geladen werden: %2</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%1&lt;/b&gt; — %2 %3, %n object(s), saved %4 from %5</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; — %2 %3, %n Objekt, gespeichert %4 von %5</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; — %2 %3, %n Objekte, gespeichert %4 von %5</numerusform>
        </translation>
    </message>
    <message>
        <source>Loaded %1. Nothing has been written to the device.</source>
        <translation>%1 geladen. Nichts wurde auf das Gerät geschrieben.</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… und %n weiteres</numerusform>
            <numerusform>… und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore Parameters</source>
        <translation>Parameter wiederherstellen</translation>
    </message>
    <message numerus="yes">
        <source>Write %n selected value(s) from %1 to %2?</source>
        <translation>
            <numerusform>%n ausgewählten Wert aus %1 nach %2 schreiben?</numerusform>
            <numerusform>%n ausgewählte Werte aus %1 nach %2 schreiben?</numerusform>
        </translation>
    </message>
    <message>
        <source>Afterwards the values are stored permanently (1010h).</source>
        <translation>Anschließend werden die Werte dauerhaft gespeichert (1010h).</translation>
    </message>
    <message>
        <source>The values are not stored permanently; they are lost at the next power cycle unless you store them.</source>
        <translation>Die Werte sind nicht dauerhaft gespeichert; sie gehen beim nächsten Aus-/Einschalten verloren, wenn sie nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <source>Not connected: the device column stays empty until a device is connected.</source>
        <translation>Nicht verbunden: die Gerätespalte bleibt leer, bis ein Gerät verbunden ist.</translation>
    </message>
    <message numerus="yes">
        <source>Reading %n object(s) from the device…</source>
        <translation>
            <numerusform>Lese %n Objekt vom Gerät…</numerusform>
            <numerusform>Lese %n Objekte vom Gerät…</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading the device failed: %1</source>
        <translation>Lesen des Geräts fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>The comparison shows the device after the restore.</source>
        <translation>Der Vergleich zeigt das Gerät nach der Wiederherstellung.</translation>
    </message>
    <message>
        <source>Compared %1 with the device. Nothing has been written.</source>
        <translation>%1 mit dem Gerät verglichen. Nichts wurde geschrieben.</translation>
    </message>
    <message numerus="yes">
        <source>Compared; %n object(s) could not be read: %1</source>
        <translation>
            <numerusform>Verglichen; %n Objekt konnte nicht gelesen werden: %1</numerusform>
            <numerusform>Verglichen; %n Objekte konnten nicht gelesen werden: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>Standardwerte</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>Schreibe %n Wert…</numerusform>
            <numerusform>Schreibe %n Werte…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Restored %n value(s)%1.</source>
        <translation>
            <numerusform>%n Wert wiederhergestellt%1.</numerusform>
            <numerusform>%n Werte wiederhergestellt%1.</numerusform>
        </translation>
    </message>
    <message>
        <source> and stored them permanently</source>
        <translation> und dauerhaft gespeichert</translation>
    </message>
    <message>
        <source>Restore incomplete: %1 written, %2 failed, %3 skipped (see the report).</source>
        <translation>Wiederherstellung unvollständig: %1 geschrieben, %2 fehlgeschlagen, %3 übersprungen (siehe Bericht).</translation>
    </message>
    <message numerus="yes">
        <source>&amp;Restore %n Selected…</source>
        <translation>
            <numerusform>%n Ausgewählten &amp;wiederherstellen…</numerusform>
            <numerusform>%n Ausgewählte &amp;wiederherstellen…</numerusform>
        </translation>
    </message>
    <message>
        <source>Not compared: the file is from vendor %1, product %2, but the device reports vendor %3, product %4 (1018h). Connect the device the set belongs to.</source>
        <translation>Nicht verglichen: Die Datei stammt von Hersteller %1, Produkt %2, das Gerät meldet aber Hersteller %3, Produkt %4 (1018h). Verbinden Sie das Gerät, zu dem der Satz gehört.</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Save &amp;Report…</source>
        <translation>&amp;Bericht speichern…</translation>
    </message>
    <message>
        <source>Save Comparison Report</source>
        <translation>Vergleichsbericht speichern</translation>
    </message>
    <message>
        <source>Saved the comparison to %1</source>
        <translation>Vergleich in %1 gespeichert</translation>
    </message>
    <message>
        <source>Nothing compared yet: no report saved</source>
        <translation>Noch nichts verglichen: kein Bericht gespeichert</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Report not saved to %1: %2</source>
        <translation>Bericht nicht in %1 gespeichert: %2</translation>
    </message>
    <message>
        <source>Compare with &amp;File…</source>
        <translation>Mit &amp;Datei vergleichen…</translation>
    </message>
    <message>
        <source>Compare the loaded set with another file instead of the device</source>
        <translation>Den geladenen Satz mit einer anderen Datei statt mit dem Gerät vergleichen</translation>
    </message>
    <message>
        <source>Compare with Parameter Set</source>
        <translation>Mit Parametersatz vergleichen</translation>
    </message>
    <message>
        <source>Load a parameter set first</source>
        <translation>Laden Sie zuerst einen Parametersatz</translation>
    </message>
    <message>
        <source>Compared %1 with %2. Nothing has been written; Re-read Device compares with the device again.</source>
        <translation>%1 mit %2 verglichen. Nichts wurde geschrieben; Gerät neu lesen vergleicht wieder mit dem Gerät.</translation>
    </message>
    <message>
        <source>Save the comparison as a PDF report (identity, date, files and the differences) or every row as a CSV file</source>
        <translation>Den Vergleich als PDF-Bericht (Identität, Datum, Dateien und die Unterschiede) oder jede Zeile als CSV-Datei speichern</translation>
    </message>
    <message>
        <source>PDF report (*.pdf)</source>
        <translation>PDF-Bericht (*.pdf)</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Another Unit</source>
        <translation>Anderes Exemplar</translation>
    </message>
    <message>
        <source>Compare Anyway</source>
        <translation>Trotzdem vergleichen</translation>
    </message>
    <message>
        <source>The file was read from another unit of this product: serial number %1, this device reports %2 (1018h.4). Values such as calibrations and offsets belong to one unit.</source>
        <translation>Die Datei wurde von einem anderen Exemplar dieses Produkts gelesen: Seriennummer %1, dieses Gerät meldet %2 (1018h.4). Werte wie Kalibrierungen und Offsets gehören zu einem Exemplar.</translation>
    </message>
    <message>
        <source>Compared %1 with another unit. %2 Nothing has been written.</source>
        <translation>%1 mit einem anderen Exemplar verglichen. %2 Nichts wurde geschrieben.</translation>
    </message>
    <message>
        <source>Compare with this unit anyway?</source>
        <translation>Trotzdem mit diesem Exemplar vergleichen?</translation>
    </message>
    <message>
        <source>Not compared: %1</source>
        <translation>Nicht verglichen: %1</translation>
    </message>
</context>
<context>
    <name>db::widgets::ParameterSetActions</name>
    <message>
        <source>&amp;Back Up…</source>
        <translation>&amp;Sichern…</translation>
    </message>
    <message>
        <source>&amp;Compare / Restore…</source>
        <translation>&amp;Vergleichen / Wiederherstellen…</translation>
    </message>
    <message>
        <source>&amp;Store Permanently</source>
        <translation>Dauerhaft &amp;speichern</translation>
    </message>
    <message>
        <source>Restore &amp;Factory Defaults…</source>
        <translation>&amp;Werkseinstellungen wiederherstellen…</translation>
    </message>
    <message>
        <source>Export &amp;DCF…</source>
        <translation>&amp;DCF exportieren…</translation>
    </message>
    <message>
        <source>Save every storable parameter of the device to a file</source>
        <translation>Jeden speicherbaren Parameter des Geräts in eine Datei sichern</translation>
    </message>
    <message>
        <source>Load a parameter set and compare it with the device and the defaults; restore selected rows</source>
        <translation>Parametersatz laden und mit Gerät und Standardwerten vergleichen; ausgewählte Zeilen wiederherstellen</translation>
    </message>
    <message>
        <source>Save the device&apos;s current parameters in its non-volatile memory (1010h &quot;save&quot;)</source>
        <translation>Die aktuellen Parameter des Geräts im nichtflüchtigen Speicher sichern (1010h „save“)</translation>
    </message>
    <message>
        <source>Reset every parameter to the factory value (1011h &quot;load&quot;)</source>
        <translation>Jeden Parameter auf den Werkswert zurücksetzen (1011h „load“)</translation>
    </message>
    <message>
        <source>Write a CiA 306 device configuration file with the device&apos;s current values</source>
        <translation>Eine CiA-306-Gerätekonfigurationsdatei mit den aktuellen Werten des Geräts schreiben</translation>
    </message>
    <message>
        <source>Back Up Parameters</source>
        <translation>Parameter sichern</translation>
    </message>
    <message>
        <source>Parameter sets (*.dbp);;All files (*)</source>
        <translation>Parametersätze (*.dbp);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Backing up parameters…</source>
        <translation>Parameter werden gesichert…</translation>
    </message>
    <message>
        <source>partial backup: %1 of %2 objects could not be read; not a complete set</source>
        <translation>Teilsicherung: %1 von %2 Objekten konnten nicht gelesen werden; kein vollständiger Satz</translation>
    </message>
    <message>
        <source>Backup incomplete, %1 not written: %2
%3
Failed: %4%5</source>
        <translation>Sicherung unvollständig, %1 nicht geschrieben: %2
%3
Fehlgeschlagen: %4%5</translation>
    </message>
    <message numerus="yes">
        <source>The %n parameter(s) read and the failures are in %1.</source>
        <translation>
            <numerusform>Der gelesene Parameter und die Fehler stehen in %1.</numerusform>
            <numerusform>Die %n gelesenen Parameter und die Fehler stehen in %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> and %n more</source>
        <translation>
            <numerusform> und %n weiteres</numerusform>
            <numerusform> und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <source>Backup not saved: %1</source>
        <translation>Sicherung nicht gespeichert: %1</translation>
    </message>
    <message numerus="yes">
        <source>Backed up %n parameter(s) to %1</source>
        <translation>
            <numerusform>%n Parameter nach %1 gesichert</numerusform>
            <numerusform>%n Parameter nach %1 gesichert</numerusform>
        </translation>
    </message>
    <message>
        <source>Export DCF</source>
        <translation>DCF exportieren</translation>
    </message>
    <message>
        <source>Device configuration files (*.dcf);;All files (*)</source>
        <translation>Gerätekonfigurationsdateien (*.dcf);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Reading parameters for the DCF…</source>
        <translation>Lese Parameter für die DCF…</translation>
    </message>
    <message>
        <source>DCF not written: %1</source>
        <translation>DCF nicht geschrieben: %1</translation>
    </message>
    <message numerus="yes">
        <source>Exported the DCF with %n value(s) to %1</source>
        <translation>
            <numerusform>DCF mit %n Wert nach %1 exportiert</numerusform>
            <numerusform>DCF mit %n Werten nach %1 exportiert</numerusform>
        </translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Backup cancelled; nothing was saved</source>
        <translation>Sicherung abgebrochen; nichts gespeichert</translation>
    </message>
    <message>
        <source>Store Parameters</source>
        <translation>Parameter speichern</translation>
    </message>
    <message>
        <source>Store the current parameters of %1 permanently (1010h &quot;save&quot;)?

The values the device holds now become its power-up values.</source>
        <translation>Die aktuellen Parameter von %1 dauerhaft speichern (1010h „save“)?

Die jetzigen Werte des Geräts werden seine Einschaltwerte.</translation>
    </message>
    <message>
        <source>Parameters stored permanently</source>
        <translation>Parameter dauerhaft gespeichert</translation>
    </message>
    <message>
        <source>Factory defaults restored (1011h); they take effect after the next reset or power cycle</source>
        <translation>Werkseinstellungen wiederhergestellt (1011h); sie wirken nach dem nächsten Reset oder Aus-/Einschalten</translation>
    </message>
    <message>
        <source>Refused by the device: %1</source>
        <translation>Vom Gerät abgelehnt: %1</translation>
    </message>
    <message>
        <source>Every parameter of %1 returns to its factory value: positions, limits, velocities, I/O functions, PDO mappings and communication settings you changed are lost.</source>
        <translation>Jeder Parameter von %1 kehrt auf den Werkswert zurück: geänderte Positionen, Grenzen, Geschwindigkeiten, E/A-Funktionen, PDO-Mappings und Kommunikationseinstellungen gehen verloren.</translation>
    </message>
    <message>
        <source>On a MovingCap this also deletes the Python script stored in the drive.</source>
        <translation>Bei einem MovingCap wird dabei auch das im Antrieb gespeicherte Python-Skript gelöscht.</translation>
    </message>
    <message>
        <source>Restore Factory Defaults</source>
        <translation>Werkseinstellungen wiederherstellen</translation>
    </message>
    <message>
        <source>Restore the factory defaults (1011h &quot;load&quot;)?</source>
        <translation>Werkseinstellungen wiederherstellen (1011h „load“)?</translation>
    </message>
    <message>
        <source>This cannot be undone from drivebench unless you have a backup.</source>
        <translation>Ohne Sicherung lässt sich das in drivebench nicht rückgängig machen.</translation>
    </message>
    <message>
        <source>Back Up First…</source>
        <translation>Zuerst sichern…</translation>
    </message>
    <message>
        <source>Restore Defaults Without Backup</source>
        <translation>Werkseinstellungen ohne Sicherung wiederherstellen</translation>
    </message>
    <message>
        <source>Back Up Before Factory Defaults</source>
        <translation>Vor den Werkseinstellungen sichern</translation>
    </message>
    <message>
        <source>Factory defaults not restored: the backup did not succeed</source>
        <translation>Werkseinstellungen nicht wiederhergestellt: die Sicherung ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>all parameters</source>
        <translation>alle Parameter</translation>
    </message>
    <message>
        <source>factory defaults</source>
        <translation>Werkseinstellungen</translation>
    </message>
</context>
<context>
    <name>db::widgets::PdoPanel</name>
    <message>
        <source>Read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <source>Read the node&apos;s PDO communication and mapping objects</source>
        <translation>Die PDO-Kommunikations- und Mapping-Objekte des Knotens lesen</translation>
    </message>
    <message>
        <source>Write the changed PDOs: each is disabled, its mapping cleared, the entries written, then enabled again</source>
        <translation>Die geänderten PDOs schreiben: jedes wird deaktiviert, sein Mapping geleert, die Einträge geschrieben, dann wieder aktiviert</translation>
    </message>
    <message>
        <source>PDO</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation>COB-ID</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Inhibit</source>
        <translation>Sperrzeit</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>Ereignis</translation>
    </message>
    <message>
        <source>Mapping</source>
        <translation>Mapping</translation>
    </message>
    <message>
        <source>RPDO: the node receives it; TPDO: the node sends it</source>
        <translation>RPDO: der Knoten empfängt es; TPDO: der Knoten sendet es</translation>
    </message>
    <message>
        <source>Enabled (COB-ID bit 31 clear)</source>
        <translation>Aktiv (COB-ID Bit 31 gelöscht)</translation>
    </message>
    <message>
        <source>CAN identifier (hex)</source>
        <translation>CAN-Identifier (hexadezimal)</translation>
    </message>
    <message>
        <source>Transmission type: 0 acyclic synchronous, 1..240 every n-th SYNC, 254/255 event driven</source>
        <translation>Übertragungsart: 0 azyklisch synchron, 1..240 bei jedem n-ten SYNC, 254/255 ereignisgesteuert</translation>
    </message>
    <message>
        <source>Inhibit time in multiples of 100 µs (minimum gap between two transmissions)</source>
        <translation>Sperrzeit in Vielfachen von 100 µs (kleinster Abstand zweier Sendungen)</translation>
    </message>
    <message>
        <source>Event timer in ms (0 = off)</source>
        <translation>Ereignis-Timer in ms (0 = aus)</translation>
    </message>
    <message>
        <source>Mapped objects as index:sub/bits, in frame order</source>
        <translation>Abgebildete Objekte als Index:Sub/Bits, in der Reihenfolge im Frame</translation>
    </message>
    <message>
        <source>PDOs of node %1</source>
        <translation>PDOs von Knoten %1</translation>
    </message>
    <message>
        <source>Select a node</source>
        <translation>Knoten auswählen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no object address (e.g. 6041:0/16)</source>
        <translation>&apos;%1&apos; ist keine Objektadresse (z. B. 6041:0/16)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the length is 1..64 bits</source>
        <translation>&apos;%1&apos;: die Länge ist 1..64 Bit</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: give the length in bits (%2/16)</source>
        <translation>&apos;%1&apos;: Länge in Bit angeben (%2/16)</translation>
    </message>
    <message>
        <source>the mapping has %1 bits; a PDO carries at most 64</source>
        <translation>das Mapping hat %1 Bit; ein PDO trägt höchstens 64</translation>
    </message>
    <message>
        <source>%1 entries; at most %2</source>
        <translation>%1 Einträge; höchstens %2</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is no COB-ID</source>
        <translation>%1: &apos;%2&apos; ist keine COB-ID</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is no transmission type (0..255)</source>
        <translation>%1: &apos;%2&apos; ist keine Übertragungsart (0..255)</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not 0..65535</source>
        <translation>%1: &apos;%2&apos; liegt nicht in 0..65535</translation>
    </message>
    <message>
        <source>communication %1h, mapping %2h</source>
        <translation>Kommunikation %1h, Mapping %2h</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>reading the PDOs of node %1…</source>
        <translation>lese die PDOs von Knoten %1…</translation>
    </message>
    <message>
        <source>reading the PDOs failed: %1</source>
        <translation>Lesen der PDOs fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>node %1 has no PDO objects</source>
        <translation>Knoten %1 hat keine PDO-Objekte</translation>
    </message>
    <message numerus="yes">
        <source>%n PDO(s) read</source>
        <translation>
            <numerusform>%n PDO gelesen</numerusform>
            <numerusform>%n PDOs gelesen</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing changed</source>
        <translation>nichts geändert</translation>
    </message>
    <message numerus="yes">
        <source>%n PDO(s) written</source>
        <translation>
            <numerusform>%n PDO geschrieben</numerusform>
            <numerusform>%n PDOs geschrieben</numerusform>
        </translation>
    </message>
    <message>
        <source>writing %1…</source>
        <translation>Schreibe %1…</translation>
    </message>
    <message>
        <source>%1 of node %2</source>
        <translation>%1 von Knoten %2</translation>
    </message>
    <message>
        <source>%1 not written (it stays disabled): %2</source>
        <translation>%1 nicht geschrieben (es bleibt deaktiviert): %2</translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopeAnalysisDialog</name>
    <message>
        <source>Analysis: %1</source>
        <translation>Analyse: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; from %2 s to %3 s (%4 samples)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; von %2 s bis %3 s (%4 Messwerte)</translation>
    </message>
    <message>
        <source>Figures</source>
        <translation>Kennwerte</translation>
    </message>
    <message>
        <source>frequency (Hz)</source>
        <translation>Frequenz (Hz)</translation>
    </message>
    <message>
        <source>amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <source>amplitude [%1]</source>
        <translation>Amplitude [%1]</translation>
    </message>
    <message>
        <source>No spectrum: %1</source>
        <translation>Kein Spektrum: %1</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>Effektivwert</translation>
    </message>
    <message>
        <source>Std. deviation</source>
        <translation>Standardabweichung</translation>
    </message>
    <message>
        <source>Min / max</source>
        <translation>Min / Max</translation>
    </message>
    <message>
        <source>Peak-peak</source>
        <translation>Spitze-Spitze</translation>
    </message>
    <message>
        <source>Spectral peak</source>
        <translation>Spektrale Spitze</translation>
    </message>
    <message>
        <source>Sample period</source>
        <translation>Abtastperiode</translation>
    </message>
    <message>
        <source>Step response</source>
        <translation>Sprungantwort</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Rise time (10–90 %)</source>
        <translation>Anstiegszeit (10–90 %)</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>Überschwingen</translation>
    </message>
    <message>
        <source>Peak</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <source>, %1 after the step start</source>
        <translation>, %1 nach Sprungbeginn</translation>
    </message>
    <message>
        <source>Settling time (2 %)</source>
        <translation>Einschwingzeit (2 %)</translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopeChannelModel</name>
    <message>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Skalierung</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>Rate (ms)</source>
        <translation>Rate (ms)</translation>
    </message>
    <message>
        <source>%1 [%2]
device: %3
display = raw × %4 + %5
%6 samples, %7 lost
double-click the name to change the colour</source>
        <translation>%1 [%2]
Gerät: %3
Anzeige = Rohwert × %4 + %5
%6 Messwerte, %7 verloren
Doppelklick auf den Namen ändert die Farbe</translation>
    </message>
    <message>
        <source>max</source>
        <translation>max</translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopeMeasurements</name>
    <message>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>at A</source>
        <translation>bei A</translation>
    </message>
    <message>
        <source>at B</source>
        <translation>bei B</translation>
    </message>
    <message>
        <source>B − A</source>
        <translation>B − A</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>Effektivwert</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>P-P</source>
        <translation>S-S</translation>
    </message>
    <message>
        <source>dy: value at B minus value at A</source>
        <translation>dy: Wert bei B minus Wert bei A</translation>
    </message>
    <message>
        <source>peak-to-peak between A and B</source>
        <translation>Spitze-Spitze zwischen A und B</translation>
    </message>
    <message>
        <source>Cursors off: switch them on to measure between A and B.</source>
        <translation>Cursor aus: zum Messen zwischen A und B einschalten.</translation>
    </message>
    <message>
        <source>&lt;b&gt;A&lt;/b&gt; %1 s &amp;nbsp; &lt;b&gt;B&lt;/b&gt; %2 s &amp;nbsp; &lt;b&gt;Δt&lt;/b&gt; %3 s &amp;nbsp; &lt;b&gt;1/Δt&lt;/b&gt; %4 Hz</source>
        <translation>&lt;b&gt;A&lt;/b&gt; %1 s &amp;nbsp; &lt;b&gt;B&lt;/b&gt; %2 s &amp;nbsp; &lt;b&gt;Δt&lt;/b&gt; %3 s &amp;nbsp; &lt;b&gt;1/Δt&lt;/b&gt; %4 Hz</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopePage</name>
    <message>
        <source>Add channels by address, or drag objects here from the object dictionary.</source>
        <translation>Kanäle über die Adresse hinzufügen oder Objekte aus dem Objektverzeichnis hierher ziehen.</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>Kanäle</translation>
    </message>
    <message>
        <source>Object address, e.g. 6064:0, 6078:0</source>
        <translation>Objektadresse, z. B. 6064:0, 6078:0</translation>
    </message>
    <message>
        <source>Object addresses INDEX:SUB (hex), separated by commas</source>
        <translation>Objektadressen INDEX:SUB (hex), durch Kommas getrennt</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>max rate</source>
        <translation>max. Rate</translation>
    </message>
    <message>
        <source>Polling period of new channels (max rate: as fast as the link allows)</source>
        <translation>Abfrageperiode neuer Kanäle (max. Rate: so schnell die Verbindung erlaubt)</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>Rate</translation>
    </message>
    <message>
        <source>Acquisition</source>
        <translation>Erfassung</translation>
    </message>
    <message>
        <source>Run (until Stop)</source>
        <translation>Laufen (bis Stopp)</translation>
    </message>
    <message>
        <source>Single (one trigger)</source>
        <translation>Einzeln (ein Trigger)</translation>
    </message>
    <message>
        <source>Normal (re-arm)</source>
        <translation>Normal (neu scharf schalten)</translation>
    </message>
    <message>
        <source>Roll (last seconds)</source>
        <translation>Rollen (letzte Sekunden)</translation>
    </message>
    <message>
        <source>rising edge</source>
        <translation>steigende Flanke</translation>
    </message>
    <message>
        <source>falling edge</source>
        <translation>fallende Flanke</translation>
    </message>
    <message>
        <source>above level</source>
        <translation>über Pegel</translation>
    </message>
    <message>
        <source>below level</source>
        <translation>unter Pegel</translation>
    </message>
    <message>
        <source>inside window</source>
        <translation>im Fenster</translation>
    </message>
    <message>
        <source>outside window</source>
        <translation>außerhalb des Fensters</translation>
    </message>
    <message>
        <source>bit set</source>
        <translation>Bit gesetzt</translation>
    </message>
    <message>
        <source>bit clear</source>
        <translation>Bit gelöscht</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Roll window</source>
        <translation>Rollfenster</translation>
    </message>
    <message>
        <source>Trigger on</source>
        <translation>Trigger auf</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Bedingung</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Pegel</translation>
    </message>
    <message>
        <source>Level 2</source>
        <translation>Pegel 2</translation>
    </message>
    <message>
        <source>Bit</source>
        <translation>Bit</translation>
    </message>
    <message>
        <source>Pre-trigger</source>
        <translation>Vor-Trigger</translation>
    </message>
    <message>
        <source>Post-trigger</source>
        <translation>Nach-Trigger</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Messwerte</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Autoskalierung</translation>
    </message>
    <message>
        <source>Fit time and values to the data (key A)</source>
        <translation>Zeit und Werte an die Daten anpassen (Taste A)</translation>
    </message>
    <message>
        <source>Cursors</source>
        <translation>Cursor</translation>
    </message>
    <message>
        <source>A/B cursors: drag the lines to measure</source>
        <translation>A/B-Cursor: zum Messen die Linien ziehen</translation>
    </message>
    <message>
        <source>Analyse…</source>
        <translation>Analysieren…</translation>
    </message>
    <message>
        <source>Spectrum and step response of the selected channel between the cursors (or in view)</source>
        <translation>Spektrum und Sprungantwort des gewählten Kanals zwischen den Cursorn (oder im sichtbaren Bereich)</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Öffnen…</translation>
    </message>
    <message>
        <source>Whole recording…</source>
        <translation>Ganze Aufzeichnung…</translation>
    </message>
    <message>
        <source>Visible range…</source>
        <translation>Sichtbarer Bereich…</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>CSV exportieren</translation>
    </message>
    <message>
        <source>Export image…</source>
        <translation>Bild exportieren…</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>inaktiv</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>Aufzeichnung läuft</translation>
    </message>
    <message>
        <source>armed, waiting for the trigger</source>
        <translation>scharf, warte auf den Trigger</translation>
    </message>
    <message>
        <source>triggered</source>
        <translation>getriggert</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>gestoppt</translation>
    </message>
    <message>
        <source>%1, %2 lost</source>
        <translation>%1, %2 verloren</translation>
    </message>
    <message>
        <source>no drivebench objects in the drop</source>
        <translation>keine drivebench-Objekte im abgelegten Inhalt</translation>
    </message>
    <message>
        <source>line %1 &quot;%2&quot;: %3</source>
        <translation>Zeile %1 „%2“: %3</translation>
    </message>
    <message>
        <source>the drop holds no object address</source>
        <translation>der abgelegte Inhalt enthält keine Objektadresse</translation>
    </message>
    <message>
        <source>stop recording to change the channels</source>
        <translation>Aufzeichnung stoppen, um die Kanäle zu ändern</translation>
    </message>
    <message>
        <source>no device: connect one to add channels from it</source>
        <translation>kein Gerät: eines verbinden, um Kanäle davon hinzuzufügen</translation>
    </message>
    <message>
        <source>%1 is already recorded</source>
        <translation>%1 wird bereits aufgezeichnet</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n channel(s) ready; press Start to record.</source>
        <translation>
            <numerusform>%n Kanal bereit; Start drücken zum Aufzeichnen.</numerusform>
            <numerusform>%n Kanäle bereit; Start drücken zum Aufzeichnen.</numerusform>
        </translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2</source>
        <translation>„%1“: %2</translation>
    </message>
    <message>
        <source>Channel colour</source>
        <translation>Kanalfarbe</translation>
    </message>
    <message>
        <source>No connected device: connect one first.</source>
        <translation>Kein verbundenes Gerät: zuerst eines verbinden.</translation>
    </message>
    <message>
        <source>No channels: add an object address or drag objects here.</source>
        <translation>Keine Kanäle: Objektadresse hinzufügen oder Objekte hierher ziehen.</translation>
    </message>
    <message>
        <source>%1: choose a .png or .pdf file name</source>
        <translation>%1: einen Dateinamen mit .png oder .pdf wählen</translation>
    </message>
    <message>
        <source>%1: cannot be written</source>
        <translation>%1: kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>Aufzeichnung öffnen</translation>
    </message>
    <message>
        <source>Recordings (*.csv);;All files (*)</source>
        <translation>Aufzeichnungen (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Export recording</source>
        <translation>Aufzeichnung exportieren</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Export image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <source>PNG image (*.png);;PDF (*.pdf)</source>
        <translation>PNG-Bild (*.png);;PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Nothing to analyse: record or open a recording first.</source>
        <translation>Nichts zu analysieren: zuerst aufzeichnen oder eine Aufzeichnung öffnen.</translation>
    </message>
    <message>
        <source>PDO %1</source>
        <translation>PDO %1</translation>
    </message>
    <message>
        <source>Sampled passively from the PDO with COB-ID %1, bytes %2..%3</source>
        <translation>Passiv aus dem PDO mit COB-ID %1 abgetastet, Bytes %2..%3</translation>
    </message>
    <message>
        <source>, expected every %1 ms (later frames count as lost samples)</source>
        <translation>, erwartet alle %1 ms (spätere Frames zählen als verlorene Messwerte)</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Polling (SDO)</source>
        <translation>Abfrage (SDO)</translation>
    </message>
    <message>
        <source>PDO (passive)</source>
        <translation>PDO (passiv)</translation>
    </message>
    <message>
        <source>Polling: the host reads each object by SDO at the rate above.
PDO (passive): samples the TPDOs that already carry the objects; sends nothing and changes neither the PDO configuration nor the NMT state (the node must be operational).</source>
        <translation>Abfrage: der Rechner liest jedes Objekt per SDO mit der obigen Rate.
PDO (passiv): tastet die TPDOs ab, die die Objekte bereits übertragen; sendet nichts und ändert weder die PDO-Konfiguration noch den NMT-Zustand (der Knoten muss operational sein).</translation>
    </message>
    <message>
        <source>Map to TPDO…</source>
        <translation>Auf TPDO mappen…</translation>
    </message>
    <message>
        <source>Map the objects that are in no TPDO into one (changes the device&apos;s PDO configuration; asks first)</source>
        <translation>Objekte, die in keinem TPDO sind, in eines mappen (ändert die PDO-Konfiguration des Geräts; fragt vorher)</translation>
    </message>
    <message>
        <source>PDO channels need a connected CANopen device</source>
        <translation>PDO-Kanäle brauchen ein verbundenes CANopen-Gerät</translation>
    </message>
    <message>
        <source>wait for the PDO configuration being read</source>
        <translation>warten, bis die PDO-Konfiguration gelesen ist</translation>
    </message>
    <message>
        <source>Reading the PDO configuration of node %1…</source>
        <translation>Lese die PDO-Konfiguration von Knoten %1…</translation>
    </message>
    <message>
        <source>the connection changed or recording started</source>
        <translation>die Verbindung hat sich geändert oder die Aufzeichnung hat begonnen</translation>
    </message>
    <message>
        <source> (use &quot;Map to TPDO…&quot; to map it)</source>
        <translation> (mit „Auf TPDO mappen…“ mappen)</translation>
    </message>
    <message numerus="yes">
        <source>%n PDO channel(s) added; press Start to record (node %1 must be operational).</source>
        <translation>
            <numerusform>%n PDO-Kanal hinzugefügt; Start drücken zum Aufzeichnen (Knoten %1 muss operational sein).</numerusform>
            <numerusform>%n PDO-Kanäle hinzugefügt; Start drücken zum Aufzeichnen (Knoten %1 muss operational sein).</numerusform>
        </translation>
    </message>
    <message>
        <source>Map to TPDO</source>
        <translation>Auf TPDO mappen</translation>
    </message>
    <message>
        <source>TPDO number of node %1:</source>
        <translation>TPDO-Nummer von Knoten %1:</translation>
    </message>
    <message>
        <source>Change the PDO configuration?</source>
        <translation>PDO-Konfiguration ändern?</translation>
    </message>
    <message>
        <source>This changes the PDO configuration of node %1: TPDO%2 will carry %3, sent every %4 ms. Whatever TPDO%2 carried before is replaced (in the device&apos;s RAM; nothing is stored). A PLC or other master using TPDO%2 will see the change.

Change it?</source>
        <translation>Das ändert die PDO-Konfiguration von Knoten %1: TPDO%2 überträgt dann %3, gesendet alle %4 ms. Was TPDO%2 bisher übertrug, wird ersetzt (im RAM des Geräts; nichts wird gespeichert). Eine SPS oder ein anderer Master, der TPDO%2 nutzt, sieht die Änderung.

Ändern?</translation>
    </message>
    <message>
        <source>nothing to map (add PDO channels first; stop recording)</source>
        <translation>nichts zu mappen (zuerst PDO-Kanäle hinzufügen; Aufzeichnung stoppen)</translation>
    </message>
    <message>
        <source>Writing TPDO%1 of node %2…</source>
        <translation>Schreibe TPDO%1 von Knoten %2…</translation>
    </message>
    <message>
        <source>TPDO%1 was not changed completely (it may be left disabled)</source>
        <translation>TPDO%1 wurde nicht vollständig geändert (es kann deaktiviert geblieben sein)</translation>
    </message>
    <message>
        <source>No PDO within %1 s for %2: %3 (the scope never changes the NMT state).</source>
        <translation>Kein PDO innerhalb von %1 s für %2: %3 (das Oszilloskop ändert den NMT-Zustand nie).</translation>
    </message>
    <message>
        <source>a PDO channel needs a CANopen connection</source>
        <translation>ein PDO-Kanal braucht eine CANopen-Verbindung</translation>
    </message>
    <message>
        <source>Object address, e.g. %1</source>
        <translation>Objektadresse, z. B. %1</translation>
    </message>
    <message>
        <source>Object addresses (%1 and %2, as the device writes them), separated by commas</source>
        <translation>Objektadressen (%1 und %2, wie das Gerät sie schreibt), durch Kommas getrennt</translation>
    </message>
    <message>
        <source>the dropped objects have %1 addresses, this device&apos;s are %2 addresses (like %3)</source>
        <translation>die abgelegten Objekte haben %1-Adressen, die dieses Geräts sind %2-Adressen (wie %3)</translation>
    </message>
    <message>
        <source>Type an object address such as %1.</source>
        <translation>Geben Sie eine Objektadresse wie %1 ein.</translation>
    </message>
    <message>
        <source>%1: cannot be written: %2</source>
        <translation>%1: kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source> node %1</source>
        <translation> Knoten %1</translation>
    </message>
    <message>
        <source>Device: none</source>
        <translation>Gerät: keines</translation>
    </message>
    <message>
        <source>Device: %1</source>
        <translation>Gerät: %1</translation>
    </message>
    <message>
        <source>Devices: %1</source>
        <translation>Geräte: %1</translation>
    </message>
    <message>
        <source>Recorded: %1</source>
        <translation>Aufgezeichnet: %1</translation>
    </message>
    <message>
        <source>Trigger: %1, %2; %3 s before, %4 s after; time 0 = trigger</source>
        <translation>Trigger: %1, %2; %3 s davor, %4 s danach; Zeit 0 = Trigger</translation>
    </message>
    <message>
        <source>No trigger: time from the start of the recording</source>
        <translation>Kein Trigger: Zeit ab Beginn der Aufzeichnung</translation>
    </message>
    <message>
        <source>%1 is not connected: connect it or remove its channels</source>
        <translation>%1 ist nicht verbunden: verbinden oder seine Kanäle entfernen</translation>
    </message>
    <message>
        <source>%1 would be recorded twice from %2: remove one</source>
        <translation>%1 würde zweimal von %2 aufgezeichnet: einen entfernen</translation>
    </message>
</context>
<context>
    <name>db::widgets::ScopePlot</name>
    <message>
        <source>raw</source>
        <translation>roh</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>time from the trigger (s)</source>
        <translation>Zeit ab Trigger (s)</translation>
    </message>
</context>
<context>
    <name>devices</name>
    <message>
        <source>no connection</source>
        <translation>keine Verbindung</translation>
    </message>
    <message>
        <source>this device has no axis: %1 describes no CiA 402 drive (no 6064h; give ?eds=FILE) and is no ACTIVE Cube</source>
        <translation>dieses Gerät hat keine Achse: %1 beschreibt keinen CiA-402-Antrieb (kein 6064h; ?eds=DATEI angeben) und ist kein ACTIVE Cube</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Commissioning tool for industrial drives.</source>
        <translation>Inbetriebnahme-Werkzeug für industrielle Antriebe.</translation>
    </message>
    <message>
        <source>Start a simulated MovingCap in-process and connect to it over RefGo and over CANopen (SLCAN, node 50).</source>
        <translation>Einen simulierten MovingCap im Prozess starten und über RefGo und CANopen (SLCAN, Knoten 50) verbinden.</translation>
    </message>
    <message>
        <source>Connect to &lt;uri&gt; at start, e.g. refgo://192.168.2.150.</source>
        <translation>Beim Start mit &lt;uri&gt; verbinden, z. B. refgo://192.168.2.150.</translation>
    </message>
    <message>
        <source>Demo drive listening at %1</source>
        <translation>Demo-Antrieb lauscht unter %1</translation>
    </message>
    <message>
        <source>Demo drive without CANopen: %1</source>
        <translation>Demo-Antrieb ohne CANopen: %1</translation>
    </message>
    <message>
        <source>Demo drive CANopen at %1</source>
        <translation>Demo-Antrieb CANopen unter %1</translation>
    </message>
    <message>
        <source>Language of the window: de or en (default: DRIVEBENCH_LANG, the setting, LC_ALL, LC_MESSAGES, LANG).</source>
        <translation>Sprache des Fensters: de oder en (Standard: DRIVEBENCH_LANG, die Einstellung, LC_ALL, LC_MESSAGES, LANG).</translation>
    </message>
    <message>
        <source>Demo NM17x displays (nodes 2, 3, 4) at canopen+slcan://127.0.0.1:%1?node=2</source>
        <translation>Demo-NM17x-Anzeigen (Knoten 2, 3, 4) unter canopen+slcan://127.0.0.1:%1?node=2</translation>
    </message>
    <message>
        <source>%1 added to the description library</source>
        <translation>%1 in die Beschreibungsbibliothek aufgenommen</translation>
    </message>
    <message>
        <source>%1 not added to the description library: %2</source>
        <translation>%1 nicht in die Beschreibungsbibliothek aufgenommen: %2</translation>
    </message>
    <message>
        <source>Demo ACTIVE Cube at %1</source>
        <translation>Demo-ACTIVE-Cube unter %1</translation>
    </message>
    <message>
        <source>Cannot start the demo drive: %1</source>
        <translation>Der Demo-Antrieb kann nicht gestartet werden: %1</translation>
    </message>
    <message>
        <source>Demo ACTIVE Cube not started: %1</source>
        <translation>Demo-ACTIVE-Cube nicht gestartet: %1</translation>
    </message>
    <message>
        <source>Demo NM17x displays not started: %1</source>
        <translation>Demo-NM17x-Anzeigen nicht gestartet: %1</translation>
    </message>
</context>
<context>
    <name>protocols</name>
    <message>
        <source>%1 names no interface or host</source>
        <translation>%1 nennt keine Schnittstelle und keinen Host</translation>
    </message>
    <message>
        <source>MovingCap RefGo (ASCII over TCP)</source>
        <translation>MovingCap RefGo (ASCII über TCP)</translation>
    </message>
    <message>
        <source>CANopen over SLCAN in TCP (MovingCap ETH: node 50)</source>
        <translation>CANopen über SLCAN in TCP (MovingCap ETH: Knoten 50)</translation>
    </message>
    <message>
        <source>CANopen over Qt CAN plugin &apos;%1&apos;</source>
        <translation>CANopen über Qt-CAN-Plugin „%1“</translation>
    </message>
    <message>
        <source>Bonfiglioli ACTIVE Cube over VABus/TCP</source>
        <translation>Bonfiglioli ACTIVE Cube über VABus/TCP</translation>
    </message>
    <message>
        <source>no description matches node %1 (%2); its objects are read by index (give ?eds=FILE)</source>
        <translation>keine Beschreibung passt zu Knoten %1 (%2); seine Objekte werden über den Index gelesen (?eds=DATEI angeben)</translation>
    </message>
    <message>
        <source>no description matches node %1 (%2); its objects are read by index (give ?eds=FILE, or put the device&apos;s EDS into %3)</source>
        <translation>keine Beschreibung passt zu Knoten %1 (%2); seine Objekte werden über den Index gelesen (?eds=DATEI angeben oder die EDS des Geräts nach %3 legen)</translation>
    </message>
    <message>
        <source>the description %1 for node %2 does not load: %3</source>
        <translation>die Beschreibung %1 für Knoten %2 lässt sich nicht laden: %3</translation>
    </message>
    <message>
        <source>description for node %1 (%2): %3 (%4)</source>
        <translation>Beschreibung für Knoten %1 (%2): %3 (%4)</translation>
    </message>
</context>
<context>
    <name>sim</name>
    <message>
        <source>Serve RefGo on this TCP port (0 = chosen by the OS).</source>
        <translation>RefGo auf diesem TCP-Port bereitstellen (0 = vom Betriebssystem gewählt).</translation>
    </message>
    <message>
        <source>Preset an object before serving, e.g. 3511:8=110 (repeatable).</source>
        <translation>Ein Objekt vor dem Start vorbelegen, z. B. 3511:8=110 (wiederholbar).</translation>
    </message>
    <message>
        <source>Serve CANopen (movingcap: node 50) as SLCAN over TCP on this port (0 = chosen by the OS).</source>
        <translation>CANopen (movingcap: Knoten 50) als SLCAN über TCP auf diesem Port bereitstellen (0 = vom Betriebssystem gewählt).</translation>
    </message>
    <message>
        <source>canopen: also serve on this Qt virtualcan interface.</source>
        <translation>canopen: zusätzlich auf dieser Qt-virtualcan-Schnittstelle bereitstellen.</translation>
    </message>
    <message>
        <source>canopen: node ids, e.g. 1,2,5 (default 1).</source>
        <translation>canopen: Knoten-IDs, z. B. 1,2,5 (Standard 1).</translation>
    </message>
    <message>
        <source>canopen: device description of the nodes (EDS, DCF, XDD, XDC, JSON; default: the built-in test node).</source>
        <translation>canopen: Gerätebeschreibung der Knoten (EDS, DCF, XDD, XDC, JSON; Standard: der eingebaute Testknoten).</translation>
    </message>
    <message>
        <source>canopen: this node&apos;s SDO server stays silent (repeatable).</source>
        <translation>canopen: der SDO-Server dieses Knotens bleibt stumm (wiederholbar).</translation>
    </message>
    <message>
        <source>movingcap: writes to this object fail with a device error (failure mode for tests; repeatable).</source>
        <translation>movingcap: Schreibzugriffe auf dieses Objekt scheitern mit einem Gerätefehler (Fehlermodus für Tests; wiederholbar).</translation>
    </message>
    <message>
        <source>Simulated drives on 127.0.0.1.

Devices:
  movingcap   a MovingCap ETH drive (RefGo and SLCAN doors)
  canopen     CANopen nodes driven by a device description (SLCAN and/or virtualcan doors)
  nm17x       a line of Baumer NM170/NM172/NM174 displays (SLCAN and/or virtualcan doors, control socket)
  acu         a Bonfiglioli ACTIVE Cube with CM-VABus/TCP (PLC port)</source>
        <translation>Simulierte Antriebe auf 127.0.0.1.

Geräte:
  movingcap   ein MovingCap-ETH-Antrieb (RefGo- und SLCAN-Zugang)
  canopen     CANopen-Knoten nach einer Gerätebeschreibung (SLCAN- und/oder virtualcan-Zugang)
  nm17x       eine Linie von Baumer-NM170/NM172/NM174-Anzeigen (SLCAN- und/oder virtualcan-Zugang, Steuer-Socket)
  acu         ein Bonfiglioli ACTIVE Cube mit CM-VABus/TCP (SPS-Port)</translation>
    </message>
    <message>
        <source>nm17x: the displays on the bus, VARIANT@NODE, e.g. nm172@127,nm172@127,nm174@5 (each its own serial number).</source>
        <translation>nm17x: die Anzeigen am Bus, VARIANTE@KNOTEN, z. B. nm172@127,nm172@127,nm174@5 (jede mit eigener Seriennummer).</translation>
    </message>
    <message>
        <source>nm17x: line-based control socket on this TCP port (turn a shaft, press a key; 0 = chosen by the OS).</source>
        <translation>nm17x: zeilenbasierter Steuer-Socket auf diesem TCP-Port (Welle drehen, Taste drücken; 0 = vom Betriebssystem gewählt).</translation>
    </message>
    <message>
        <source>acu: serve VABus/TCP (the PLC port) on this TCP port (0 = chosen by the OS).</source>
        <translation>acu: VABus/TCP (den SPS-Port) auf diesem TCP-Port bereitstellen (0 = vom Betriebssystem gewählt).</translation>
    </message>
    <message>
        <source>acu: time without exchange before the reaction of parameter 388 (default 10000).</source>
        <translation>acu: Zeit ohne Datenaustausch bis zur Reaktion nach Parameter 388 (Standard 10000).</translation>
    </message>
    <message>
        <source>acu: failure mode for tests: silent, garbage, slow, drop-after or split (every answer in 1-byte TCP segments).</source>
        <translation>acu: Fehlermodus für Tests: silent, garbage, slow, drop-after oder split (jede Antwort in 1-Byte-TCP-Segmenten).</translation>
    </message>
    <message>
        <source>acu: --fail slow delays every answer this long (default 2000).</source>
        <translation>acu: --fail slow verzögert jede Antwort um diese Zeit (Standard 2000).</translation>
    </message>
    <message>
        <source>acu: --fail drop-after closes the connection after this many answers (default 1).</source>
        <translation>acu: --fail drop-after schließt die Verbindung nach so vielen Antworten (Standard 1).</translation>
    </message>
    <message>
        <source>acu: answer nothing for this long after start, as the module initialising after power-on (up to 20000).</source>
        <translation>acu: nach dem Start so lange nicht antworten, wie das Modul beim Initialisieren nach dem Einschalten (bis 20000).</translation>
    </message>
    <message>
        <source>acu: a system bus slave with this node id (1-63) behind the module (repeatable).</source>
        <translation>acu: ein Systembus-Slave mit dieser Knoten-ID (1-63) hinter dem Modul (wiederholbar).</translation>
    </message>
    <message>
        <source>movingcap: the drive starts in fault with this EMCY code (hexadecimal, e.g. 7121).</source>
        <translation>movingcap: der Antrieb startet mit diesem EMCY-Code in Störung (hexadezimal, z. B. 7121).</translation>
    </message>
    <message>
        <source>nm17x: the bus&apos;s bit rate in bit/s (default 125000); SLCAN clients set to another one hear nothing.</source>
        <translation>nm17x: die Bitrate des Busses in bit/s (Standard 125000); auf eine andere eingestellte SLCAN-Clients hören nichts.</translation>
    </message>
    <message>
        <source>acu: start in fault with this code (hex as parameter 260 shows it, e.g. 2714 for F2714).</source>
        <translation>acu: mit dieser Störung starten (hexadezimal wie Parameter 260 sie zeigt, z. B. 2714 für F2714).</translation>
    </message>
    <message>
        <source>acu: simulated inputs off at start, comma-separated: mains, sto, or the limit switches on: limit-pos, limit-neg.</source>
        <translation>acu: beim Start abgeschaltete simulierte Eingänge, durch Kommas getrennt: mains, sto, oder aktive Endschalter: limit-pos, limit-neg.</translation>
    </message>
    <message>
        <source>movingcap, acu: read commands from standard input while serving, one a line: state, standstill, drop (abort every client: a cut cable), fault CODE; movingcap: heartbeat off|on; acu: mains on|off, sto on|off, master SPEED (the electronic gear&apos;s master, u/s), watchdog MS.</source>
        <translation>movingcap, acu: liest während des Betriebs Befehle von der Standardeingabe, einen pro Zeile: state, standstill, drop (alle Clients abbrechen: ein durchtrenntes Kabel), fault CODE; movingcap: heartbeat off|on; acu: mains on|off, sto on|off, master SPEED (der Master des elektronischen Getriebes, u/s), watchdog MS.</translation>
    </message>
    <message>
        <source>Which device: movingcap, canopen, nm17x or acu.</source>
        <translation>Welches Gerät: movingcap, canopen, nm17x oder acu.</translation>
    </message>
    <message>
        <source>give --slcan-port PORT (0..65535) and/or --virtualcan IFACE</source>
        <translation>--slcan-port PORT (0..65535) und/oder --virtualcan SCHNITTSTELLE angeben</translation>
    </message>
    <message>
        <source>give the device to simulate (movingcap, canopen, nm17x or acu), e.g. drivebench-sim movingcap --refgo-port PORT [--slcan-port PORT]</source>
        <translation>das zu simulierende Gerät angeben (movingcap, canopen, nm17x oder acu), z. B. drivebench-sim movingcap --refgo-port PORT [--slcan-port PORT]</translation>
    </message>
    <message>
        <source>no door to serve; give --refgo-port PORT and/or --slcan-port PORT (0 = any free port)</source>
        <translation>kein Zugang zu bedienen; --refgo-port PORT und/oder --slcan-port PORT angeben (0 = ein freier Port)</translation>
    </message>
    <message>
        <source>%1 takes a port number 0..65535</source>
        <translation>%1 erwartet eine Portnummer 0..65535</translation>
    </message>
    <message>
        <source>--set takes INDEX:SUB=VALUE, not &apos;%1&apos;</source>
        <translation>--set erwartet INDEX:SUB=WERT, nicht „%1“</translation>
    </message>
    <message>
        <source>--reject-write takes INDEX:SUB, not &apos;%1&apos;</source>
        <translation>--reject-write erwartet INDEX:SUB, nicht „%1“</translation>
    </message>
    <message>
        <source>nm17x needs --slcan-port PORT (0..65535) and/or --virtualcan IFACE; --control-port takes a port 0..65535</source>
        <translation>nm17x braucht --slcan-port PORT (0..65535) und/oder --virtualcan SCHNITTSTELLE; --control-port erwartet einen Port 0..65535</translation>
    </message>
    <message>
        <source>--bitrate takes bit/s, e.g. 125000 or 250000</source>
        <translation>--bitrate erwartet bit/s, z. B. 125000 oder 250000</translation>
    </message>
    <message>
        <source>acu needs --vabus-port PORT (0 = any free port)</source>
        <translation>acu braucht --vabus-port PORT (0 = ein freier Port)</translation>
    </message>
    <message>
        <source>--vabus-port takes a port number 0..65535</source>
        <translation>--vabus-port erwartet eine Portnummer 0..65535</translation>
    </message>
    <message>
        <source>--watchdog-ms takes a time in ms (1 or more)</source>
        <translation>--watchdog-ms erwartet eine Zeit in ms (1 oder mehr)</translation>
    </message>
    <message>
        <source>--slow-ms, --drop-after and --startup-delay-ms take a number</source>
        <translation>--slow-ms, --drop-after und --startup-delay-ms erwarten eine Zahl</translation>
    </message>
    <message>
        <source>--fail takes silent, garbage, slow, drop-after or split, not &apos;%1&apos;</source>
        <translation>--fail erwartet silent, garbage, slow, drop-after oder split, nicht „%1“</translation>
    </message>
    <message>
        <source>--slave takes a node id 1..63, not &apos;%1&apos;</source>
        <translation>--slave erwartet eine Knotennummer 1..63, nicht „%1“</translation>
    </message>
    <message>
        <source>--acu-fault takes a fault code in hex, e.g. 2714, not &apos;%1&apos;</source>
        <translation>--acu-fault erwartet einen Störungscode hexadezimal, z. B. 2714, nicht „%1“</translation>
    </message>
    <message>
        <source>--acu-inputs takes mains, sto, limit-pos, limit-neg, not &apos;%1&apos;</source>
        <translation>--acu-inputs erwartet mains, sto, limit-pos, limit-neg, nicht „%1“</translation>
    </message>
</context>
</TS>
