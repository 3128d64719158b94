using System;
using System.Collections;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;

namespace URWPGSim2D.Server.Items;

/// <summary>
/// An item's state for strategies, the equivalent of the original's <c>Mission.HtMissionVariables</c>:
/// string keys (exactly the original's, e.g. <c>Ball_3_Left_Status</c>, <c>IsYellowFish2Caught</c>,
/// <c>Ball0InHole</c>) and string values (the original's ints as invariant text, which
/// <c>Convert.ToInt32</c> reads). Keys keep the order they were added in. Refreshed by the referee
/// after every cycle; setting a small integer allocates nothing.
/// </summary>
internal sealed class MissionVariables : IReadOnlyDictionary<string, string>
{
    private static readonly string[] Small = CreateSmall();

    private readonly List<string> _keys = new();
    private readonly Dictionary<string, string> _values = new(StringComparer.Ordinal);

    /// <summary>Number of keys.</summary>
    public int Count => _keys.Count;

    /// <summary>The keys in the order they were added.</summary>
    public IEnumerable<string> Keys => _keys;

    /// <summary>The values in key order.</summary>
    public IEnumerable<string> Values
    {
        get
        {
            foreach (string key in _keys)
            {
                yield return _values[key];
            }
        }
    }

    /// <summary>The value of a key.</summary>
    /// <exception cref="KeyNotFoundException">No such key.</exception>
    public string this[string key] => _values[key];

    /// <summary>Sets a key to text (adds it at the end when new).</summary>
    public void Set(string key, string value)
    {
        if (!_values.ContainsKey(key))
        {
            _keys.Add(key);
        }

        _values[key] = value;
    }

    /// <summary>Sets a key to an integer, written in invariant culture.</summary>
    public void Set(string key, int value) =>
        Set(key, value >= 0 && value < Small.Length ? Small[value] : value.ToString(CultureInfo.InvariantCulture));

    /// <summary>The value of a key as an integer (what a strategy's <c>Convert.ToInt32</c> gives).</summary>
    public int GetInt32(string key) => int.Parse(_values[key], NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture);

    /// <inheritdoc/>
    public bool ContainsKey(string key) => _values.ContainsKey(key);

    /// <inheritdoc/>
    public bool TryGetValue(string key, [MaybeNullWhen(false)] out string value) => _values.TryGetValue(key, out value);

    /// <inheritdoc/>
    public IEnumerator<KeyValuePair<string, string>> GetEnumerator()
    {
        foreach (string key in _keys)
        {
            yield return new KeyValuePair<string, string>(key, _values[key]);
        }
    }

    /// <inheritdoc/>
    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();

    private static string[] CreateSmall()
    {
        var s = new string[64];
        for (int i = 0; i < s.Length; i++)
        {
            s[i] = i.ToString(CultureInfo.InvariantCulture);
        }

        return s;
    }
}
