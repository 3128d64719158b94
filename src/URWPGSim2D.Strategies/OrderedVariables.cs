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

    /// <summary>The variables in their order, without allocating (a <c>foreach</c> over this table itself; through an interface the enumerator is boxed).</summary>
    public Enumerator GetEnumerator() => new(this);

    /// <inheritdoc/>
    IEnumerator<KeyValuePair<string, string>> IEnumerable<KeyValuePair<string, string>>.GetEnumerator() => GetEnumerator();

    /// <inheritdoc/>
    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();

    /// <summary>Walks the variables in their order; a value type, so a <c>foreach</c> over the table allocates nothing.</summary>
    public struct Enumerator : IEnumerator<KeyValuePair<string, string>>
    {
        private readonly OrderedVariables _table;
        private int _index;

        internal Enumerator(OrderedVariables table)
        {
            _table = table;
            _index = -1;
        }

        /// <inheritdoc/>
        public readonly KeyValuePair<string, string> Current
        {
            get
            {
                string key = _table._keys[_index];
                return new KeyValuePair<string, string>(key, _table._values[key]);
            }
        }

        /// <inheritdoc/>
        readonly object IEnumerator.Current => Current;

        /// <inheritdoc/>
        public bool MoveNext() => ++_index < _table._keys.Count;

        /// <inheritdoc/>
        public void Reset() => _index = -1;

        /// <inheritdoc/>
        public readonly void Dispose()
        {
        }
    }

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
