using System;
using System.Collections;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;

namespace URWPGSim2D.Strategies;

/// <summary>
/// An item's variables (the original's <c>HtMissionVariables</c>) in the order their keys were
/// first set. The referee's table derives from it; a snapshot that a strategy reads on its own
/// thread holds its own copy (<see cref="CopyFrom"/>), which allocates nothing once its keys are those of the source.
/// </summary>
public class OrderedVariables : IReadOnlyDictionary<string, string>
{
    private readonly List<string> _keys = [];
    private readonly Dictionary<string, string> _values = new(StringComparer.Ordinal);

    /// <inheritdoc/>
    public int Count => _keys.Count;

    /// <inheritdoc/>
    public IEnumerable<string> Keys => _keys;

    /// <inheritdoc/>
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

    /// <inheritdoc/>
    public string this[string key] => _values[key];

    /// <summary>Sets a variable; a new key goes last.</summary>
    public void Set(string key, string value)
    {
        if (!_values.ContainsKey(key))
        {
            _keys.Add(key);
        }

        _values[key] = value;
    }

    /// <summary>Makes this table equal to <paramref name="source"/>: the same keys in the same order, the same values.</summary>
    public void CopyFrom(OrderedVariables source)
    {
        if (!SameKeys(source))
        {
            _keys.Clear();
            _values.Clear();
            _keys.AddRange(source._keys);
        }

        foreach (string key in source._keys)
        {
            _values[key] = source._values[key];
        }
    }

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

    private bool SameKeys(OrderedVariables source)
    {
        if (source._keys.Count != _keys.Count)
        {
            return false;
        }

        for (int i = 0; i < _keys.Count; i++)
        {
            if (!string.Equals(source._keys[i], _keys[i], StringComparison.Ordinal))
            {
                return false;
            }
        }

        return true;
    }
}
