namespace Microsoft.Xna.Framework;

/// <summary>
/// The array forms of the vectors' transforms (<see cref="Vector2.Transform(Vector2[], ref Matrix, Vector2[])"/> and the rest):
/// one element's transform applied to every element of a range, into a range of another (or the same) array.
/// </summary>
internal static class VectorArrays
{
    /// <summary>Applies <paramref name="transform"/> with <paramref name="by"/> to every element of <paramref name="sourceArray"/>, into the same indices of <paramref name="destinationArray"/>.</summary>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">The destination is shorter than the source.</exception>
    internal static void Map<T, TBy>(T[] sourceArray, in TBy by, T[] destinationArray, Func<T, TBy, T> transform)
    {
        ArgumentNullException.ThrowIfNull(sourceArray);
        ArgumentNullException.ThrowIfNull(destinationArray);
        if (destinationArray.Length < sourceArray.Length)
        {
            throw new ArgumentException("The destination array is shorter than the source array.", nameof(destinationArray));
        }

        Map(sourceArray, 0, by, destinationArray, 0, sourceArray.Length, transform);
    }

    /// <summary>Applies <paramref name="transform"/> with <paramref name="by"/> to <paramref name="length"/> elements from <paramref name="sourceIndex"/>, into <paramref name="destinationArray"/> from <paramref name="destinationIndex"/>.</summary>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">A range does not fit its array.</exception>
    internal static void Map<T, TBy>(T[] sourceArray, int sourceIndex, in TBy by, T[] destinationArray, int destinationIndex, int length, Func<T, TBy, T> transform)
    {
        ArgumentNullException.ThrowIfNull(sourceArray);
        ArgumentNullException.ThrowIfNull(destinationArray);
        if (sourceIndex < 0 || destinationIndex < 0 || length < 0 || sourceArray.Length - sourceIndex < length || destinationArray.Length - destinationIndex < length)
        {
            throw new ArgumentException("The range does not fit the arrays.", nameof(length));
        }

        for (int i = 0; i < length; i++)
        {
            destinationArray[destinationIndex + i] = transform(sourceArray[sourceIndex + i], by);
        }
    }
}
