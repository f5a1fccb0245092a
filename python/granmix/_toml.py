"""A scene given as a dict, written as TOML text for granmix.Scene.from_dict.

Top-level dicts become tables ([mixture], [dsmc], ...), dicts inside them inline tables, lists arrays; strings,
booleans, integers and floats (repr: the shortest text that reads back as the same double) are written as TOML
has them. The text is then read and checked exactly as a scene file is (theory::load_scene_text)."""
import json
import math
import numbers
import re

_BARE_KEY = re.compile(r'^[A-Za-z0-9_-]+$')


def _key(k):
    if not isinstance(k, str):
        raise TypeError(f'scene keys are strings, not {type(k).__name__} ({k!r})')
    return k if _BARE_KEY.match(k) else json.dumps(k, ensure_ascii=False)


def _value(v, where):
    if isinstance(v, bool):
        return 'true' if v else 'false'
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)  # JSON's escapes are TOML's basic-string escapes
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        x = float(v)
        if math.isnan(x):
            return 'nan'
        if math.isinf(x):
            return 'inf' if x > 0 else '-inf'
        return repr(x)
    if isinstance(v, dict):
        return '{' + ', '.join(f'{_key(k)} = {_value(x, f"{where}.{k}")}' for k, x in v.items()) + '}'
    if hasattr(v, 'tolist') and not isinstance(v, (list, tuple)):  # numpy arrays and scalars
        return _value(v.tolist(), where)
    if isinstance(v, (list, tuple)):
        return '[' + ', '.join(_value(x, f'{where}[{i}]') for i, x in enumerate(v)) + ']'
    if v is None:
        raise TypeError(f'{where}: None has no TOML form (leave the key out)')
    raise TypeError(f'{where}: {type(v).__name__} has no TOML form')


def dumps(scene):
    """The TOML text of a scene dict ({"scene": {...}, "mixture": {...}, ...})."""
    if not isinstance(scene, dict):
        raise TypeError(f'a scene dict maps table names to tables, not {type(scene).__name__}')
    lines = [f'{_key(k)} = {_value(v, k)}' for k, v in scene.items() if not isinstance(v, dict)]
    for name, table in scene.items():
        if not isinstance(table, dict):
            continue
        if lines:
            lines.append('')
        lines.append(f'[{_key(name)}]')
        lines.extend(f'{_key(k)} = {_value(v, f"{name}.{k}")}' for k, v in table.items())
    return '\n'.join(lines) + '\n'
