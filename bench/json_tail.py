"""The last JSON object in a program's output (one line or pretty-printed;
other output around it is skipped): shared by bench/stuff_wild.py and
bench/stuff_compare.sh, which read `bccmis stuff --json` and `stuff_peers`."""
import json


def last_json(text):
    """The last JSON object (a dict) in text, or None."""
    decoder, found = json.JSONDecoder(), None
    i = text.find("{")
    while i >= 0:
        try:
            obj, end = decoder.raw_decode(text, i)
            if isinstance(obj, dict):
                found = obj
            i = text.find("{", end)
        except json.JSONDecodeError:
            i = text.find("{", i + 1)
    return found
