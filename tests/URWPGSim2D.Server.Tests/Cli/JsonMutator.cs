namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// Mutates a valid JSON input into a likely-invalid one, deterministically from a seed: byte flips,
/// truncation, deleted or duplicated spans, swapped values (numbers, strings, null, arrays, objects),
/// extreme numbers, NaN, lone surrogates and line breaks in strings, deep nesting, a BOM, bytes that
/// are not UTF-8. Several mutations may stack in one case.
/// </summary>
internal sealed class JsonMutator
{
    private static readonly string[] Values =
    [
        "0", "-0", "-1", "1e39", "-1e39", "1e999", "3.4028236e38", "1e-46", "NaN", "Infinity", "9223372036854775808",
        "18446744073709551616", "0.1", "null", "true", "false", "\"\"", "\"x\"", "\"\\ud800\"", "\"\\udc00x\"",
        "\"a\\nb\"", "\"\\u2028\"", "\"\\u0000\"", "[]", "{}", "[0]", "[0,0,0]", "[[0,0]]", "{\"type\":\"circle\"}",
        "\"circle\"", "\"fish\"", "\"polygon\"", "\"match\"", "\"batch\"",
    ];

    private const string Punctuation = "{}[],:\"\\ \n0-e.";

    private readonly Random _random;

    /// <summary>Creates a mutator whose choices follow <paramref name="seed"/>.</summary>
    public JsonMutator(int seed) => _random = new Random(seed);

    /// <summary>One mutated copy of <paramref name="input"/>: one to three mutations stacked.</summary>
    public byte[] Mutate(byte[] input)
    {
        var bytes = new List<byte>(input);
        int count = 1 + _random.Next(3);
        for (int k = 0; k < count; k++)
        {
            MutateOnce(bytes);
        }

        return [.. bytes];
    }

    private void MutateOnce(List<byte> b)
    {
        switch (_random.Next(12))
        {
            case 0: // flip a bit
                if (b.Count > 0)
                {
                    int i = _random.Next(b.Count);
                    b[i] ^= (byte)(1 << _random.Next(8));
                }

                break;
            case 1: // truncate
                int keep = _random.Next(b.Count + 1);
                b.RemoveRange(keep, b.Count - keep);
                break;
            case 2: // delete a span
                if (b.Count > 0)
                {
                    int i = _random.Next(b.Count);
                    b.RemoveRange(i, Math.Min(b.Count - i, 1 + _random.Next(16)));
                }

                break;
            case 3: // duplicate a span (a repeated field or array element)
                if (b.Count > 0)
                {
                    int i = _random.Next(b.Count);
                    int n = Math.Min(b.Count - i, 1 + _random.Next(64));
                    b.InsertRange(i, b.GetRange(i, n));
                }

                break;
            case 4: // replace a value (the token after a ':' or '[' or ',') with another kind or an extreme
            case 5:
            case 6:
                ReplaceValue(b);
                break;
            case 7: // deep nesting
                int depth = 1 + _random.Next(200);
                int at = _random.Next(b.Count + 1);
                b.InsertRange(at, Encoding.ASCII.GetBytes(new string('[', depth)));
                break;
            case 8: // a BOM in front (valid) or in the middle (not)
                b.InsertRange(_random.Next(2) == 0 ? 0 : _random.Next(b.Count + 1), [0xEF, 0xBB, 0xBF]);
                break;
            case 9: // bytes that are not UTF-8
                b.Insert(_random.Next(b.Count + 1), _random.Next(3) switch { 0 => (byte)0xFF, 1 => (byte)0xC3, _ => (byte)0x80 });
                break;
            case 10: // a random ASCII character
                b.Insert(_random.Next(b.Count + 1), (byte)Punctuation[_random.Next(Punctuation.Length)]);
                break;
            default: // grow an array: repeat the text between a '[' and its first ','
                GrowArray(b);
                break;
        }
    }

    private void ReplaceValue(List<byte> b)
    {
        var starts = new List<int>();
        for (int i = 0; i < b.Count; i++)
        {
            if (b[i] is (byte)':' or (byte)'[' or (byte)',')
            {
                starts.Add(i + 1);
            }
        }

        if (starts.Count == 0)
        {
            return;
        }

        int start = starts[_random.Next(starts.Count)];
        while (start < b.Count && b[start] == (byte)' ')
        {
            start++;
        }

        int end = ValueEnd(b, start);
        b.RemoveRange(start, end - start);
        b.InsertRange(start, Encoding.UTF8.GetBytes(Values[_random.Next(Values.Length)]));
    }

    // The end of the JSON value starting at start (balanced brackets, strings skipped), or of the token.
    private static int ValueEnd(List<byte> b, int start)
    {
        int depth = 0;
        bool inString = false;
        for (int i = start; i < b.Count; i++)
        {
            byte c = b[i];
            if (inString)
            {
                if (c == (byte)'\\')
                {
                    i++;
                }
                else if (c == (byte)'"')
                {
                    inString = false;
                    if (depth == 0)
                    {
                        return i + 1;
                    }
                }

                continue;
            }

            switch (c)
            {
                case (byte)'"': inString = true; break;
                case (byte)'[' or (byte)'{': depth++; break;
                case (byte)']' or (byte)'}':
                    if (depth == 0)
                    {
                        return i;
                    }

                    if (--depth == 0)
                    {
                        return i + 1;
                    }

                    break;
                case (byte)',' when depth == 0: return i;
            }
        }

        return b.Count;
    }

    private void GrowArray(List<byte> b)
    {
        int open = b.IndexOf((byte)'[', _random.Next(b.Count + 1));
        if (open < 0)
        {
            return;
        }

        int end = ValueEnd(b, open + 1);
        if (end <= open + 1 || end >= b.Count || b[end] != (byte)',')
        {
            return;
        }

        var element = b.GetRange(open + 1, end - open); // the element and its comma
        int times = 1 + _random.Next(50);
        for (int k = 0; k < times; k++)
        {
            b.InsertRange(open + 1, element);
        }
    }
}
