#!/usr/bin/env python3
"""Writes resources/devices/movingcap_eth.json, our own MovingCap ETH device description, from the
facts in ../shared/specs/movingcap_objects.csv and movingcap_errors.csv (movingcap.md section 6
and 7), with the spec's readings of the manual's gaps and errata applied (see FIXES below).

Run from the repository root:  python3 tools/make_movingcap_description.py
(--clean: only drop the notes about the sources from the descriptions of the existing file, which
has objects added by hand since it was generated; --german: only add the German value and bit
names to the existing file.)
"""
import csv
import re
import json
import os
import sys

SPECS = os.path.join(os.path.dirname(__file__), '..', '..', 'shared', 'specs')
OUT = os.path.join(os.path.dirname(__file__), '..', 'resources', 'devices', 'movingcap_eth.json')

# Rows the spec marks as typos of other objects (errata 8 and 9): not separate objects.
DROP = {(0x3101, 4), (0x3403, 3)}

# Types the manual leaves out; the spec gives the CiA 301/402 standard type (section 6).
TYPES = {0x1002: 'UNSIGNED32', 0x1003: 'UNSIGNED32', 0x603F: 'UNSIGNED16', 0x608F: 'UNSIGNED32',
         0x6091: 'UNSIGNED32', 0x6092: 'UNSIGNED32', 0x60FC: 'INTEGER32'}
ACCESS = {0x608F: 'rw'}

# CiA 301 mandatory objects that every CANopen device has ([STD], not in the manual); the
# vendor ID 0x053B is from the spec's Appendix C ([EXT]).
EXTRA = [
    dict(index=0x1000, sub=0, name='Device type', type='UNSIGNED32', access='ro',
         default='0x00020192', description='[STD] CiA 301: device profile 402 (drive), '
         'additional information 0x0002 (servo drive).'),
    dict(index=0x1001, sub=0, name='Error register', type='UNSIGNED8', access='ro', trace=True,
         bits=[(0, 'generic'), (1, 'current'), (2, 'voltage'), (3, 'temperature'),
               (4, 'communication'), (5, 'device profile specific'), (7, 'manufacturer')],
         description='[STD] CiA 301 error register; sent as byte 2 of each EMCY.'),
    dict(index=0x1008, sub=0, name='Manufacturer device name', type='VISIBLE_STRING',
         access='const', default='MovingCap ETH', description='[STD] CiA 301.'),
    dict(index=0x1018, sub=0, name='Highest sub-index supported', object='Identity object',
         type='UNSIGNED8', access='const', default=4, description='[STD] CiA 301.'),
    dict(index=0x1018, sub=1, name='Vendor-ID', object='Identity object', type='UNSIGNED32',
         access='ro', default='0x0000053B', description='[EXT] Fullmo vendor ID (spec App. C).'),
    dict(index=0x1018, sub=2, name='Product code', object='Identity object', type='UNSIGNED32',
         access='ro', description='[STD] CiA 301.'),
    dict(index=0x1018, sub=3, name='Revision number', object='Identity object',
         type='UNSIGNED32', access='ro', description='[STD] CiA 301.'),
    dict(index=0x1018, sub=4, name='Serial number', object='Identity object', type='UNSIGNED32',
         access='ro', description='[STD] CiA 301.'),
]

# Defaults: the spec's Appendix C gives the XDD values where the manual has none ([EXT]).
DEFAULTS = {(0x605A, 0): 1, (0x6083, 0): 1000, (0x6084, 0): 1000, (0x6085, 0): 1000,
            (0x6067, 0): 5000, (0x6068, 0): 100, (0x607D, 1): -2147483647,
            (0x607D, 2): 2147483647, (0x608F, 1): 65536, (0x608F, 2): 1, (0x6091, 1): 1,
            (0x6091, 2): 1, (0x6092, 2): 1, (0x60F2, 0): 0, (0x6098, 0): 35}
LIMITS = {(0x6083, 0): (1, 20000), (0x6084, 0): (1, 20000), (0x6085, 0): (1, 20000)}

MODES = {'0': 'No mode', '1': 'Profile position', '3': 'Velocity', '6': 'Homing'}
ENUMS = {
    0x6060: MODES, 0x6061: MODES,
    0x605A: {'0': 'Disable drive function', '1': 'Slow down ramp, then switch on disabled',
             '2': 'Quick stop ramp, then switch on disabled',
             '5': 'Slow down ramp, stay in quick stop', '6': 'Quick stop ramp, stay in quick stop'},
    0x6098: {'35': 'Set zero (35)', '37': 'Set zero (37)', '-18': 'Hard stop positive',
             '-19': 'Hard stop negative'},
    0x3301: {'1': 'Rabbit', '2': 'Hedgehog', '3': 'Float'},
}
OUTPUT_FUNCTIONS = {'0': 'None', '1': 'Statusword 6041h monitor', '2': 'Error register 1002h monitor',
                    '3': 'Limit monitoring right/left', '4': 'Position feedback',
                    '5': 'Drive without fault or warning', '6': 'Position and status feedback'}

STATUSWORD_BITS = [(0, 'ready to switch on'), (1, 'switched on'), (2, 'operation enabled'),
                   (3, 'fault'), (4, 'voltage enabled'), (5, 'quick stop'),
                   (6, 'switch on disabled'), (7, 'warning'), (8, 'drive moving'), (9, 'remote'),
                   (10, 'target reached'), (11, 'internal limit active'),
                   (12, 'set-point acknowledge / homing attained'),
                   (13, 'following error / homing error')]
CONTROLWORD_BITS = [(0, 'switch on'), (1, 'enable voltage'), (2, 'quick stop (active low)'),
                    (3, 'enable operation'), (4, 'new set-point / start homing'),
                    (5, 'change set immediately'), (6, 'relative'), (7, 'fault reset'), (8, 'halt')]
STATUS_REGISTER_BITS = [(0, 'Error over volt (Uzk)'), (1, 'Error under volt (Uzk)'),
                        (2, 'Error Ack'), (3, 'Error over temp'), (4, 'Error I2T / Derating'),
                        (5, 'Abort connection'), (6, 'Error stroke'), (7, 'Error communication'),
                        (8, 'Error Sensor'), (9, 'Error Hardware / Software Enable'),
                        (11, 'Error Over Current'), (12, 'Error External Force / Torque'),
                        (13, 'Error Needs Voltage Reset'), (16, 'Warning Sensor')]
INPUT_BITS = [(16 + i, 'IN%d' % (i + 1)) for i in range(10)]
OUTPUT_BITS = [(16 + i, 'OUT%d' % (i + 1)) for i in range(4)]
BITS = {(0x6041, 0): STATUSWORD_BITS, (0x6040, 0): CONTROLWORD_BITS,
        (0x1002, 0): STATUS_REGISTER_BITS, (0x60FD, 0): INPUT_BITS, (0x60FE, 1): OUTPUT_BITS,
        (0x3510, 1): INPUT_BITS,
        (0x3401, 0x1A): [(0, 'off during acceleration'), (1, 'off during deceleration'),
                         (2, 'off at constant velocity'), (3, 'following error off')]}

# Units shown next to values (the CSV's long unit text stays in the description).
UNITS = {'user-defined units': 'units', 'user units/s or rpm': 'units/s', 'ms': 'ms', 'mA': 'mA',
         'degC': '°C', 'g': 'g', 'degree': '°'}
PERCENT_TENTHS = {(0x6073, 0), (0x6078, 0), (0x3401, 0x15), (0x3401, 0x16), (0x3401, 0x18),
                  (0x3300, 4), (0x3301, 14)}

# Process data and commands are not part of a parameter set.
NOT_STORABLE = {0x6040, 0x607A, 0x60FF, 0x60FE, 0x3510, 0x1010, 0x1011, 0x6060}
PDO = {0x6040, 0x6041, 0x6060, 0x6061, 0x6064, 0x606C, 0x6078, 0x607A, 0x60FF, 0x60FD, 0x60FE,
       0x1002, 0x603F, 0x3510, 0x60FC, 0x1001}
TRACE = {0x6040, 0x6041, 0x6061, 0x6064, 0x606C, 0x6078, 0x607A, 0x60FF, 0x60FD, 0x60FE, 0x1002,
         0x60FC, 0x1001}


# Fault texts: English where the first sentence of the table's text does not do, and the German
# texts of the drive's emergency list.
ERROR_TEXTS = {
    'ERROR_OVER_CURRENT': ('Over-current', 'Überstrom'),
    'ERROR_OVER_VOLT': (None, 'Überspannung der UZK-Leistungsversorgung des Motors'),
    'ERROR_UNDER_VOLT': (None, 'Unterspannung der UZK-Leistungsversorgung des Motors'),
    'ERROR_OVER_TEMP': (None, 'Übertemperatur'),
    'ERROR_DERATING': (None, 'Derating'),
    'ERROR_ACK': (None, 'Quittierungsfehler'),
    'ERROR_STROKE': ('Blocking / blocked travel / following error too large',
                     'Blockade / Blockfahrt / Schleppfehler zu groß'),
    'ERROR_COMMUNICATION': (None, 'Motorkommunikationsfehler'),
    'ERROR_SENSOR_1': (None, 'Sensor-/Encoderfehler'),
    'ERROR_HW_SW_ENABLE': (None, 'HW-Enable-Fehler (fehlende interne Freigabe) oder SW-Enable-'
                                 'Fehler (siehe Eingangsfunktion 9 Software Enable; entsteht bei '
                                 'jedem Einschaltversuch, solange der Software-Enable-Eingang '
                                 'fehlt)'),
    'ERROR_EXT_TORQUE': (None, 'Externe Krafteinwirkung / externes Moment auf den Antrieb'),
    'ERROR_NEEDS_RESET': ('A power (voltage) reset is required before further operation, e.g. '
                          'after a successful software update',
                          'Vor dem Weiterbetrieb ist ein Spannungsreset nötig, z. B. nach einem '
                          'erfolgreichen Software-Update'),
}


def user_text(text):
    """A description as users read it: without the bracketed references to where a fact was
    found ([seed ...], [STD], [EXT] ...), and with the drive's web page named as such."""
    text = re.sub(r'\s*\[(?:seed|STD|EXT|GAP|CONFLICT|UNCERTAIN)\b[^\]]*\]', '', text)
    text = re.sub(r'\s*\((?:spec|see) (?:App\.|section|§)[^)]*\)', '', text)
    text = re.sub(r"Shown as ('[^']*') in (?:the )?web footer",
                  r"The drive's web page shows it as \1", text)
    text = re.sub(r"\(shown as ('[^']*') in (?:the )?web footer\)",
                  r"(on the drive's web page: \1)", text)
    return drop_notes(text).strip()


# Sentences that talk about the sources rather than the drive (what the manual says or leaves
# out, its errata and typos) are notes for us, not for users.
NOTE = re.compile(r"not stated|\bmanual\b|Manual (?!setup)|Manual's|errata|typo|[Tt]ext example")


def drop_notes(text):
    text = text.replace('Values used in manual:', 'Common values:')
    sentences = re.split(r'(?<=\.)\s+(?=[A-Z(])', text)
    kept = [s for s in sentences if not NOTE.search(s)]
    text = ' '.join(kept)
    # "RABBIT: ..." reads as a tag; RABBIT is the drive's controller.
    text = re.sub(r'^RABBIT motor parameter: ', 'Motor parameter of the RABBIT controller: ',
                  text)
    text = re.sub(r'^RABBIT: (\w)', lambda m: 'RABBIT controller: ' + m.group(1), text)
    return text


# Value and bit names in German: the terms of the drive's German manual where it gives German
# ones, the German CiA 402 terms otherwise. Names that stay the same (IN1, Rabbit) are left out.
ENUM_DE = {
    'No mode': 'kein Modus', 'Profile position': 'Positionierbetrieb',
    'Velocity': 'Drehzahlbetrieb', 'Homing': 'Referenzierbetrieb',
    'Disable drive function': 'Antrieb direkt abschalten',
    'Slow down ramp, then switch on disabled': 'Bremsrampe, dann Einschalten gesperrt',
    'Quick stop ramp, then switch on disabled': 'Schnellhaltrampe, dann Einschalten gesperrt',
    'Slow down ramp, stay in quick stop': 'Bremsrampe, dann im Schnellhalt bleiben',
    'Quick stop ramp, stay in quick stop': 'Schnellhaltrampe, dann im Schnellhalt bleiben',
    'Set zero (35)': 'Nullposition setzen (35)', 'Set zero (37)': 'Nullposition setzen (37)',
    'Hard stop positive': 'Anschlagsreferenzierung positiv',
    'Hard stop negative': 'Anschlagsreferenzierung negativ',
    'None': 'keine', 'Statusword 6041h monitor': 'Statusword-6041h-Monitor',
    'Error register 1002h monitor': 'Error-Register-1002h-Monitor',
    'Limit monitoring right/left': 'Limitüberwachung rechts / links',
    'Position feedback': 'Rückmeldung zur Positionierung',
    'Drive without fault or warning': 'Antrieb ohne Fehler / Warnung',
    'Position and status feedback': 'Rückmeldung Position und Status',
    'No action': 'keine Aktion', 'Fault': 'Störung', 'Disable voltage': 'Spannung sperren',
    'Quick stop': 'Schnellhalt', 'Pre-operational': 'nach Pre-Operational',
    'No change': 'keine Änderung', 'Stopped': 'nach Stopped',
}
BIT_DE = {
    'ready to switch on': 'Einschaltbereit', 'switched on': 'Eingeschaltet',
    'operation enabled': 'Betrieb freigegeben', 'fault': 'Fehler',
    'voltage enabled': 'Spannung freigegeben', 'quick stop': 'Schnellhalt',
    'switch on disabled': 'Einschalten gesperrt', 'warning': 'Warnung',
    'drive moving': 'Antrieb in Bewegung', 'remote': 'Remote', 'target reached': 'Ziel erreicht',
    'internal limit active': 'interner Grenzwert aktiv',
    'set-point acknowledge / homing attained': 'Sollwert quittiert / Referenz erreicht',
    'following error / homing error': 'Schleppfehler / Referenzierfehler',
    'switch on': 'Einschalten', 'enable voltage': 'Spannung freigeben',
    'quick stop (active low)': 'Schnellhalt (nullaktiv)', 'enable operation': 'Betrieb freigeben',
    'new set-point / start homing': 'neuer Sollwert / Referenzfahrt starten',
    'change set immediately': 'Sollwert sofort übernehmen', 'relative': 'relativ',
    'fault reset': 'Fehler rücksetzen', 'halt': 'Halt',
    'generic': 'allgemein', 'current': 'Strom', 'voltage': 'Spannung',
    'temperature': 'Temperatur', 'communication': 'Kommunikation',
    'device profile specific': 'geräteprofilspezifisch', 'manufacturer': 'herstellerspezifisch',
    'Error over volt (Uzk)': 'Fehler Überspannung (Uzk)',
    'Error under volt (Uzk)': 'Fehler Unterspannung (Uzk)', 'Error Ack': 'Quittierungsfehler',
    'Error over temp': 'Fehler Übertemperatur', 'Error I2T / Derating': 'Fehler I2T / Derating',
    'Abort connection': 'Verbindungsabbruch', 'Error stroke': 'Fehler Blockade / Schleppfehler',
    'Error communication': 'Fehler Motorkommunikation', 'Error Sensor': 'Fehler Sensor',
    'Error Hardware / Software Enable': 'Fehler HW-/SW-Enable',
    'Error Over Current': 'Fehler Überstrom',
    'Error External Force / Torque': 'Fehler externe Kraft / externes Moment',
    'Error Needs Voltage Reset': 'Fehler: Spannungsreset nötig', 'Warning Sensor': 'Warnung Sensor',
    'off during acceleration': 'aus beim Beschleunigen',
    'off during deceleration': 'aus beim Bremsen',
    'off at constant velocity': 'aus bei konstanter Geschwindigkeit',
    'following error off': 'Schleppfehler aus',
}


# Units that are words.
UNIT_DE = {'units': 'Einheiten', 'units/s': 'Einheiten/s'}


def add_german(obj):
    """Adds the German names of obj's enumeration ("enum_de"), bits ("name_de") and unit
    ("unit_de")."""
    if obj.get('unit') in UNIT_DE:
        obj['unit_de'] = UNIT_DE[obj['unit']]
    german = {k: ENUM_DE[v] for k, v in obj.get('enum', {}).items() if v in ENUM_DE}
    if german:
        obj['enum_de'] = german
    for bit in obj.get('bits', []):
        if bit['name'] in BIT_DE:
            bit['name_de'] = BIT_DE[bit['name']]


def german_json(path):
    """Applies add_german() to every object of an existing description file in place."""
    with open(path, encoding='utf-8') as f:
        doc = json.load(f)
    for obj in doc['objects']:
        add_german(obj)
    with open(path, 'w', encoding='utf-8') as f:
        json.dump(doc, f, indent=1, ensure_ascii=False)
        f.write('\n')


def clean_json(path):
    """Applies drop_notes() to every description of an existing description file in place."""
    with open(path, encoding='utf-8') as f:
        doc = json.load(f)
    for obj in doc['objects']:
        if 'description' in obj:
            obj['description'] = drop_notes(obj['description']).strip()
    doc['device']['revision'] = '1'
    with open(path, 'w', encoding='utf-8') as f:
        json.dump(doc, f, indent=1, ensure_ascii=False)
        f.write('\n')


def main():
    objects = []
    with open(os.path.join(SPECS, 'movingcap_objects.csv'), newline='') as f:
        for row in csv.DictReader(f):
            index, sub = int(row['index'], 16), int(row['subindex'])
            if (index, sub) in DROP:
                continue
            dtype = (row['datatype'] or '').strip()
            dtype = TYPES.get(index, dtype.upper() if dtype and not dtype.startswith('(') else '')
            if not dtype:
                sys.exit('no type for %04X:%d' % (index, sub))
            acc = ACCESS.get(index, row['access'].strip() or 'rw')
            name = row['name'].strip()
            group = None
            if index in range(0x3511, 0x351B):
                group = 'Input function IN%d' % (index - 0x3510)
            elif index in range(0x3611, 0x3615):
                group = 'Output function OUT%d' % (index - 0x3610)
            elif '(' in name and name.endswith(')') and not name.startswith('('):
                name, group = name[:-1].split(' (', 1)
            obj = dict(index='0x%04X' % index, sub=sub, name=name, type=dtype, access=acc)
            if group:
                obj['object'] = group
            unit = row['unit'].strip()
            if (index, sub) in PERCENT_TENTHS or (index in range(0x3511, 0x351B) and sub == 10):
                obj['unit'], obj['factor'] = '%', 0.1
            elif unit in UNITS:
                obj['unit'] = UNITS[unit]
            default = DEFAULTS.get((index, sub))
            if default is None and row['default'].strip()[:1].isdigit():
                default = int(row['default'].split()[0])
            if default is not None:
                obj['default'] = default
            lo, hi = LIMITS.get((index, sub), (row['min'].strip(), row['max'].strip()))
            if str(lo) != '':
                obj['min'] = int(lo)
            if str(hi) != '':
                obj['max'] = int(hi)
            if index in ENUMS:
                obj['enum'] = ENUMS[index]
            if index in range(0x3611, 0x3615) and sub == 1:
                obj['enum'] = OUTPUT_FUNCTIONS
            if (index, sub) in BITS:
                obj['bits'] = [dict(bit=b, name=n) for b, n in BITS[(index, sub)]]
            runtime_result = index in range(0x3511, 0x351B) and sub in (3, 4)
            obj['storable'] = acc == 'rw' and index not in NOT_STORABLE and not runtime_result
            obj['pdo'] = index in PDO
            obj['trace'] = index in TRACE or (index, sub) == (0x3401, 10)
            obj['description'] = user_text(row['description'])
            objects.append(obj)
    for extra in EXTRA:
        obj = dict(extra)
        if 'description' in obj:
            obj['description'] = user_text(obj['description'])
        obj['index'] = '0x%04X' % obj['index']
        if 'bits' in obj:
            obj['bits'] = [dict(bit=b, name=n) for b, n in obj['bits']]
        obj.setdefault('storable', False)
        obj.setdefault('pdo', False)
        obj.setdefault('trace', False)
        objects.append(obj)
    for obj in objects:
        add_german(obj)
    objects.sort(key=lambda o: (int(o['index'], 16), o['sub']))

    errors = []
    with open(os.path.join(SPECS, 'movingcap_errors.csv'), newline='') as f:
        for row in csv.DictReader(f):
            english, german = ERROR_TEXTS.get(row['name'], (None, None))
            text = english or user_text(row['description'].split('.')[0])
            error = dict(code='0x%04X' % int(row['code_hex'], 16), name=row['name'], text=text)
            if german:
                error['text_de'] = german
            errors.append(error)

    doc = {
        'format': 'drivebench-device-description',
        'version': 1,
        'comment': 'drivebench\'s own description of the MovingCap ETH '
                   '(tools/make_movingcap_description.py).',
        'device': {'vendor': 'Fullmo GmbH', 'vendorId': '0x0000053B',
                   'product': 'MovingCap ETH', 'revision': '1',
                   'version': '1'},
        'objects': objects,
        'errors': errors,
    }
    with open(OUT, 'w', encoding='utf-8') as f:
        json.dump(doc, f, indent=1, ensure_ascii=False)
        f.write('\n')
    print('wrote %s: %d objects, %d error codes' % (OUT, len(objects), len(errors)))


if __name__ == '__main__':
    if sys.argv[1:2] == ['--clean']:
        clean_json(OUT)
    elif sys.argv[1:2] == ['--german']:
        german_json(OUT)
    else:
        main()
