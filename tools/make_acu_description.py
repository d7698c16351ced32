#!/usr/bin/env python3
"""Writes devices/bonfiglioli/acu.json, our own description of the ACTIVE Cube ACU parameters
reachable over VABus/TCP, from the facts in ../shared/specs/vabus_parameters.csv and
vabus_faults.csv, with the spec's readings of the gaps applied (types inferred from ranges,
the recommended reading of each contradiction).

Parameters are addressed as NUMBER:DATASET (ObjectAddress index = number, sub = data set).
A parameter with four data sets is described at data sets 0-4 (0 = all four at once); a single
one at data set 0. Values are raw: physical x 10^decimals.

Run from the repository root:  python3 tools/make_acu_description.py
"""
import csv
import json
import os
import re

SPECS = os.path.join(os.path.dirname(__file__), '..', '..', 'shared', 'specs')
OUT = os.path.join(os.path.dirname(__file__), '..', 'devices', 'bonfiglioli', 'acu.json')

# Types the table leaves open, from the parameter's use (block access needs word/double word).
TYPES = {
    12: 'VISIBLE_STRING', 17: 'VISIBLE_STRING', 18: 'VISIBLE_STRING', 19: 'VISIBLE_STRING',
    29: 'VISIBLE_STRING', 1431: 'VISIBLE_STRING', 1441: 'VISIBLE_STRING',
    211: 'INTEGER16', 213: 'INTEGER16', 240: 'INTEGER32', 372: 'UNSIGNED16',
    376: 'UNSIGNED16', 1454: 'INTEGER16', 1459: 'INTEGER16',
}
# 17 and 18 only take a block definition / block values; 19 only returns them.
ACCESS = {17: 'wo', 18: 'wo', 19: 'ro', 12: 'ro', 1431: 'ro'}
UNITS = {'min-1': 'rpm', 'rpm (min-1)': 'rpm', 'u/s2': 'u/s²'}
# Written cyclically or commands, never part of a parameter set.
VOLATILE = {17, 18, 19, 410, 484, 524, 1437, 1200, 1201, 1250, 1251, 1341, 1342, 1420, 1421,
            1455, 1456, 1457, 1458, 1459, 1460}
# Actual values worth a scope channel.
TRACE = {210, 211, 213, 228, 240, 249, 260, 270, 274, 282, 283, 411, 1107, 1108, 1109, 1129,
         1246}
# Selections as the parameter table describes them.
ENUMS = {
    388: {0: 'no reaction', 1: 'fault', 2: 'switch off', 3: 'quick stop',
          4: 'disable operation + fault', 5: 'quick stop + fault'},
    392: {0: 'free coast', 1: 'DC brake', 2: 'ramp'},
    412: {0: 'control via contacts', 1: 'control via state machine',
          2: 'control via remote contacts'},
    414: {0: 'data set switching via contacts', 1: 'data set 1', 2: 'data set 2',
          3: 'data set 3', 4: 'data set 4', 5: 'switching via contacts while not enabled'},
    434: {1: 'internal frequency setpoint', 2: 'line setpoint',
          3: 'internal frequency setpoint + line setpoint'},
    1122: {0: 'off', 1: 'encoder 1', 2: 'encoder 2/resolver', 11: 'RxPDO1.Long1 extrapolated'},
    1180: {0: 'off', 1: 'RxPDO1', 2: 'RxPDO2', 3: 'RxPDO3', 10: 'SYNC'},
    1436: {0: 'disabled', 1: 'enabled'},
    1437: {0: 'apply', 1: 'reload IP settings'},
    1454: {0: 'no override', 1: 'profile position', 2: 'velocity', 3: 'profile velocity',
           6: 'homing', 253: 'electronic gear: slave', 254: 'move away from limit switch',
           255: 'table travel record'},
}
# The selections in German, with the terms of the German parameter descriptions.
ENUMS_DE = {
    388: {0: 'keine Reaktion', 1: 'Störung', 2: 'Abschalten', 3: 'Schnellhalt',
          4: 'Stillsetzen + Störung', 5: 'Schnellhalt + Störung'},
    392: {0: 'freier Auslauf', 1: 'Gleichstrombremse', 2: 'Rampe'},
    412: {0: 'Steuerung über Kontakte', 1: 'Steuerung über Statemachine',
          2: 'Steuerung über Remote-Kontakte'},
    414: {0: 'Datensatzumschaltung über Kontakte', 1: 'Datensatz 1', 2: 'Datensatz 2',
          3: 'Datensatz 3', 4: 'Datensatz 4',
          5: 'Umschaltung über Kontakte, wenn nicht freigegeben'},
    434: {1: 'interner Frequenzsollwert', 2: 'Liniensollwert',
          3: 'interner Frequenzsollwert + Liniensollwert'},
    1122: {0: 'aus', 1: 'Drehgeber 1', 2: 'Drehgeber 2/Resolver',
           11: 'RxPDO1.Long1 extrapoliert'},
    1180: {0: 'aus'},
    1436: {0: 'deaktiviert', 1: 'aktiviert'},
    1437: {0: 'übernehmen', 1: 'IP-Einstellungen neu laden'},
    1454: {0: 'kein Override', 1: 'Profilpositionierung', 2: 'Geschwindigkeit',
           3: 'Profilgeschwindigkeit', 6: 'Referenzfahrt', 253: 'elektronisches Getriebe: Slave',
           254: 'Endschalter freifahren', 255: 'Tabellenfahrsatz'},
}
# Bits of the status and control words.
BITS = {
    411: ['ready to switch on', 'switched on', 'operation enabled', 'fault', 'voltage enabled',
          'quick stop', 'switch on disabled', 'warning', 'manufacturer specific', 'remote',
          'target reached', 'internal limit active', 'mode specific 12', 'mode specific 13',
          None, 'warning 2'],
    410: ['switch on', 'enable voltage', 'quick stop', 'enable operation', 'mode specific 4',
          'mode specific 5', 'mode specific 6', 'fault reset', 'halt', 'mode specific 9'],
}
BITS_DE = {
    411: ['Einschaltbereit', 'Eingeschaltet', 'Betrieb freigegeben', 'Fehler',
          'Spannung freigegeben', 'Schnellhalt', 'Einschalten gesperrt', 'Warnung',
          'herstellerabhängig', 'Remote', 'Ziel erreicht', 'interner Grenzwert aktiv',
          'betriebsartabhängig 12', 'betriebsartabhängig 13', None, 'Warnung 2'],
    410: ['Einschalten', 'Spannung freigeben', 'Schnellhalt', 'Betrieb freigeben',
          'betriebsartabhängig 4', 'betriebsartabhängig 5', 'betriebsartabhängig 6',
          'Fehler rücksetzen', 'Halt', 'betriebsartabhängig 9'],
}
# Groups for the editor, by parameter number.
GROUPS = [
    (0, 99, 'Inverter data'), (200, 299, 'Actual values'), (370, 379, 'Motor data'),
    (380, 399, 'Bus and error behaviour'), (400, 449, 'Control and ramps'),
    (450, 549, 'Setpoints'), (600, 699, 'Stop behaviour'), (900, 999, 'System bus'),
    (1100, 1199, 'Positioning'), (1200, 1299, 'Motion blocks and MCI'),
    (1300, 1399, 'PLC function table'), (1400, 1449, 'Network'),
    (1450, 1469, 'Motion control override'),
]
# Contradictory limits, read as recommended: 414 also takes 5 (switching while not enabled), the
# target window ends at 2^20 - 1.
LIMITS = {414: (0, 5), 1165: (0, 2 ** 20 - 1)}
IP_OCTETS = {1432: [172, 22, 1, 25], 1433: [255, 255, 255, 0], 1434: [0, 0, 0, 0],
             1435: [0, 0, 0, 0]}


def number(text, decimals):
    """A table value as a raw integer, or None."""
    t = text.strip().rstrip('?').split(' ')[0].replace(',', '.')
    if t in ('', '-'):
        return None
    sign = -1 if t.startswith('-') else 1
    t = t.lstrip('-').strip('()')
    m = re.fullmatch(r'2\^(\d+)(-1)?', t)
    if m:
        v = 2 ** int(m.group(1)) - (1 if m.group(2) else 0)
    elif t.lower().startswith('0x'):
        v = int(t, 16)
    else:
        try:
            v = float(t)
        except ValueError:
            return None
    return int(round(sign * v * 10 ** decimals))


def infer_type(row, decimals, lo, hi):
    n = int(row['number'])
    if n in TYPES:
        return TYPES[n]
    t = row['datatype']
    if 'String' in t:
        return 'VISIBLE_STRING'
    if t.startswith('Long'):
        return 'INTEGER32'
    if t.startswith('Int'):
        return 'INTEGER16'
    if t.startswith('uInt'):
        return 'UNSIGNED16'
    if (hi is not None and hi > 65535) or (lo is not None and lo < -32768):
        return 'INTEGER32'
    if lo is not None and lo < 0:
        return 'INTEGER16' if hi is None or hi <= 32767 else 'INTEGER32'
    return 'UNSIGNED16'


# A section number of the source ("7.2", "11.4.6", "11.1/11.2"), not a version ("5.3.0 or higher").
SECTION = re.compile(r'(?<![\d.])\d{1,2}\.\d{1,2}(?:\.\d{1,2})?(?!\d|\.\d| or higher)')


# What is left of worked examples and remarks once their section numbers are gone.
LEFTOVER = re.compile(r'\bDS \d|^(?:write|read) |^NB\b|^\d+[.:]$|\d+,\d+ ?(?:Hz|kW)|\d ms ->')


def clean(text):
    """The table's meaning column without references to sections or to the source."""
    text = re.sub(r'\s*\((?:\d+(?:\.\d+)*(?:,\s*)?)+\)', '', text)
    keep = [s for s in re.split(r'(?<=[.;:])\s+', text)
            if not re.search(r'manual|handbuch|example|printed|seed|\bex\.|reading|§|inferred|rejected|probably|^\x27', s, re.I)
            and not SECTION.search(s) and not LEFTOVER.search(s)]
    text = ' '.join(keep).strip()
    return re.sub(r'[;:]$', '.', text)


def tidy_name(text):
    """A parameter name without remarks about how the table printed it."""
    text = re.sub(r"\s*\((?:individual )?name not given\)|;\s*name not given", '', text)
    text = re.sub(r"\s*\((?:Einzelname|Name) nicht angegeben\)|;\s*Name nicht angegeben", '', text)
    text = re.sub(r"\s*\((?:as printed|so im Handbuch)[^)]*\)", '', text)
    return text.replace("'Function'", 'Function').strip()


# German words the table writes without umlauts.
UMLAUTS = {'Digitaleingaenge': 'Digitaleingänge', 'Stoerverhalten': 'Störverhalten',
           'Uebergang': 'Übergang', 'Verzoegerung': 'Verzögerung', 'Zaehler': 'Zähler',
           'Getriebefaktoraenderung': 'Getriebefaktoränderung', 'fuer': 'für',
           'unzulaessige': 'unzulässige', 'IP-Address': 'IP-Adresse'}


def german(text):
    """German text with its umlauts."""
    return re.sub(r'[\w-]+', lambda m: UMLAUTS.get(m.group(0), m.group(0)), text)


def group(n):
    for lo, hi, name in GROUPS:
        if lo <= n <= hi:
            return name
    return 'Other'


def warning_bits():
    """Bit names of the warning words 270 and 274 from the fault table (P270:0x0001, ...), in
    English and in German."""
    bits = {270: [None] * 16, 274: [None] * 16}
    bits_de = {270: [None] * 16, 274: [None] * 16}
    with open(os.path.join(SPECS, 'vabus_faults.csv'), newline='') as f:
        for row in csv.DictReader(f):
            m = re.fullmatch(r'P(270|274):0x([0-9A-Fa-f]{4})', row['code'])
            if not m:
                continue
            mask = int(m.group(2), 16)
            name = row['name'].split(' / ')[-1].strip()
            if mask and not mask & (mask - 1) and name.lower() != 'reserved':
                bits[int(m.group(1))][mask.bit_length() - 1] = name
                bits_de[int(m.group(1))][mask.bit_length() - 1] = german_warning(
                    row['name'].split(' / ')[0].strip(), int(m.group(1)), mask)
    return bits, bits_de


def german_warning(text, word, mask):
    """A warning bit's German name: the table's text without the keypad code ("BELT - ")."""
    if word == 270 and mask == 0x8000:
        return 'Warnstatus Applikation (274 lesen)'
    text = text.split(' - ', 1)[-1] if word == 274 else text
    return text.replace('Rechts', 'rechts').replace('Links', 'links').replace(
        'SW Endschalter', 'SW-Endschalter').replace('HW Endschalter', 'HW-Endschalter').replace('Benutzer Warnung', 'Benutzerwarnung')


def main():
    english, german_bits = warning_bits()
    BITS.update(english)
    BITS_DE.update(german_bits)
    objects = []
    with open(os.path.join(SPECS, 'vabus_parameters.csv'), newline='') as f:
        for row in csv.DictReader(f):
            if not row['number'].isdigit():
                continue
            n = int(row['number'])
            dec_text = row['decimals'].rstrip('?')
            t_hint = row['datatype']
            is_string = 'String' in t_hint or TYPES.get(n) == 'VISIBLE_STRING'
            decimals = -1 if is_string else (int(dec_text) if dec_text else 0)
            scale = max(decimals, 0)
            lo = None if is_string else number(row['min'], scale)
            hi = None if is_string else number(row['max'], scale)
            default = None if is_string else number(row['default'], scale)
            dtype = infer_type(row, scale, lo, hi)
            if n in IP_OCTETS:
                lo, hi, default = 0, 255, None
            if n in LIMITS:
                lo, hi = LIMITS[n]
            access = ACCESS.get(n)
            if not access:
                a = row['access']
                access = 'ro' if a.startswith('ro') or a.startswith('r ') else 'rw'
            unit = row['unit'].strip()
            unit = UNITS.get(unit, re.sub(r'\s*\(.*\)', '', unit).rstrip('?'))
            if unit == '-':
                unit = ''
            four = row['datasets'].startswith('1-4')
            row['name_en'] = tidy_name(row['name_en'])
            row['name_de'] = german(tidy_name(row['name_de']))
            base = dict(name=row['name_en'], type=dtype, access=access)
            if unit:
                base['unit'] = unit
            if decimals >= 0:
                base['decimals'] = decimals
            if lo is not None and n not in (1246,):
                base['min'] = lo
            if hi is not None:
                base['max'] = hi
            if n in ENUMS:
                base['enum'] = {str(k): v for k, v in ENUMS[n].items()}
            if n in ENUMS_DE:
                base['enum_de'] = {str(k): v for k, v in ENUMS_DE[n].items()}
            if n in BITS:
                base['bits'] = [dict(bit=i, name=b, **({'name_de': BITS_DE[n][i]}
                                                       if BITS_DE.get(n) and BITS_DE[n][i] else {}))
                                for i, b in enumerate(BITS[n]) if b]
            base['storable'] = access == 'rw' and n not in VOLATILE and 'index' not in row['datasets']
            if n in TRACE:
                base['trace'] = True
            text = clean(row['description'])
            base['description'] = f"{group(n)}: {text}" if text else group(n)
            for ds in (range(5) if four else [0]):
                o = dict(index=n, sub=ds)
                o.update(base)
                o['object'] = row['name_en']
                o['object_de'] = row['name_de']
                if four:
                    o['name'] = (f"{row['name_en']} (all data sets)" if ds == 0
                                 else f"{row['name_en']} (data set {ds})")
                    o['name_de'] = (f"{row['name_de']} (alle Datensätze)" if ds == 0
                                    else f"{row['name_de']} (Datensatz {ds})")
                    if ds == 0:
                        o['storable'] = False  # the four data sets are the stored values
                    if n in IP_OCTETS and ds > 0:
                        o['default'] = IP_OCTETS[n][ds - 1]
                else:
                    o['name_de'] = row['name_de']
                    if default is not None:
                        o['default'] = default
                if four and default is not None and n not in IP_OCTETS:
                    o['default'] = default
                objects.append(o)
    errors = []
    with open(os.path.join(SPECS, 'vabus_faults.csv'), newline='') as f:
        for row in csv.DictReader(f):
            code = row['code']
            if re.fullmatch(r'F\d{4}', code):
                names = row['name'].split(' / ')
                error = dict(code='0x' + code[1:], name=code, text=names[-1].strip())
                if len(names) > 1:
                    error['text_de'] = german(names[0].strip())
                errors.append(error)
    doc = {
        'format': 'drivebench-device-description', 'version': 1,
        'device': {'vendor': 'Bonfiglioli Vectron', 'product': 'ACTIVE Cube ACU (VABus/TCP)',
                   'version': '1'},
        'objects': objects,
        'errors': errors,
        'addresses': 'parameter',
    }
    with open(OUT, 'w', encoding='utf-8') as f:
        json.dump(doc, f, indent=1, ensure_ascii=False)
        f.write('\n')
    print(f'{OUT}: {len(objects)} objects, {len(errors)} fault codes')


if __name__ == '__main__':
    main()
