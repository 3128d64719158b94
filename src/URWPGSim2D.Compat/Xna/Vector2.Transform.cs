namespace Microsoft.Xna.Framework;

/// <summary>XNA 3.1's transforms of <see cref="Vector2"/> by a <see cref="Matrix"/> (row vector times matrix) or a <see cref="Quaternion"/>.</summary>
public partial struct Vector2
{
    /// <summary>Transforms a point: position·matrix with w = 1, no perspective divide (as XNA).</summary>
    /// <param name="position">The point.</param>
    /// <param name="matrix">The matrix.</param>
    /// <returns>The transformed point (the translation M41… applies).</returns>
    public static Vector2 Transform(Vector2 position, Matrix matrix) =>
        new((position.X * matrix.M11) + (position.Y * matrix.M21) + matrix.M41, (position.X * matrix.M12) + (position.Y * matrix.M22) + matrix.M42);

    /// <summary>The <c>ref</c> form of <see cref="Transform(Vector2, Matrix)"/>.</summary>
    /// <param name="position">The point.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="result">The transformed point.</param>
    public static void Transform(ref Vector2 position, ref Matrix matrix, out Vector2 result) => result = Transform(position, matrix);

    /// <summary>Transforms a direction: normal·matrix with w = 0 (the translation does not apply).</summary>
    /// <param name="normal">The direction.</param>
    /// <param name="matrix">The matrix.</param>
    /// <returns>The transformed direction.</returns>
    public static Vector2 TransformNormal(Vector2 normal, Matrix matrix) =>
        new((normal.X * matrix.M11) + (normal.Y * matrix.M21), (normal.X * matrix.M12) + (normal.Y * matrix.M22));

    /// <summary>The <c>ref</c> form of <see cref="TransformNormal(Vector2, Matrix)"/>.</summary>
    /// <param name="normal">The direction.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="result">The transformed direction.</param>
    public static void TransformNormal(ref Vector2 normal, ref Matrix matrix, out Vector2 result) => result = TransformNormal(normal, matrix);

    /// <summary>Rotates a vector by a unit quaternion (q·v·q*) as the vector (X, Y, 0), keeping X and Y.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="rotation">The rotation.</param>
    /// <returns>The rotated vector.</returns>
    public static Vector2 Transform(Vector2 value, Quaternion rotation)
    {
        var r = Vector3.Transform(new Vector3(value.X, value.Y, 0f), rotation);
        return new(r.X, r.Y);
    }

    /// <summary>The <c>ref</c> form of <see cref="Transform(Vector2, Quaternion)"/>.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="result">The rotated vector.</param>
    public static void Transform(ref Vector2 value, ref Quaternion rotation, out Vector2 result) => result = Transform(value, rotation);

    /// <summary>Transforms every point of an array (<see cref="Transform(Vector2, Matrix)"/>) into another (or the same) array.</summary>
    /// <param name="sourceArray">The points.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go, at the same indices (at least as long as the source).</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">The destination is shorter than the source.</exception>
    public static void Transform(Vector2[] sourceArray, ref Matrix matrix, Vector2[] destinationArray) =>
        VectorArrays.Map(sourceArray, matrix, destinationArray, Transform);

    /// <summary>Transforms a range of points (<see cref="Transform(Vector2, Matrix)"/>) into a range of another (or the same) array.</summary>
    /// <param name="sourceArray">The points.</param>
    /// <param name="sourceIndex">First point to transform.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go.</param>
    /// <param name="destinationIndex">Index of the first result.</param>
    /// <param name="length">Number of points.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">A range does not fit its array.</exception>
    public static void Transform(Vector2[] sourceArray, int sourceIndex, ref Matrix matrix, Vector2[] destinationArray, int destinationIndex, int length) =>
        VectorArrays.Map(sourceArray, sourceIndex, matrix, destinationArray, destinationIndex, length, Transform);

    /// <summary>Rotates every vector of an array (<see cref="Transform(Vector2, Quaternion)"/>) into another (or the same) array.</summary>
    /// <param name="sourceArray">The vectors.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="destinationArray">Where the results go, at the same indices (at least as long as the source).</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">The destination is shorter than the source.</exception>
    public static void Transform(Vector2[] sourceArray, ref Quaternion rotation, Vector2[] destinationArray) =>
        VectorArrays.Map(sourceArray, rotation, destinationArray, Transform);

    /// <summary>Rotates a range of vectors (<see cref="Transform(Vector2, Quaternion)"/>) into a range of another (or the same) array.</summary>
    /// <param name="sourceArray">The vectors.</param>
    /// <param name="sourceIndex">First vector to rotate.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="destinationArray">Where the results go.</param>
    /// <param name="destinationIndex">Index of the first result.</param>
    /// <param name="length">Number of vectors.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">A range does not fit its array.</exception>
    public static void Transform(Vector2[] sourceArray, int sourceIndex, ref Quaternion rotation, Vector2[] destinationArray, int destinationIndex, int length) =>
        VectorArrays.Map(sourceArray, sourceIndex, rotation, destinationArray, destinationIndex, length, Transform);

    /// <summary>Transforms every direction of an array (<see cref="TransformNormal(Vector2, Matrix)"/>) into another (or the same) array.</summary>
    /// <param name="sourceArray">The directions.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go, at the same indices (at least as long as the source).</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">The destination is shorter than the source.</exception>
    public static void TransformNormal(Vector2[] sourceArray, ref Matrix matrix, Vector2[] destinationArray) =>
        VectorArrays.Map(sourceArray, matrix, destinationArray, TransformNormal);

    /// <summary>Transforms a range of directions (<see cref="TransformNormal(Vector2, Matrix)"/>) into a range of another (or the same) array.</summary>
    /// <param name="sourceArray">The directions.</param>
    /// <param name="sourceIndex">First direction to transform.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go.</param>
    /// <param name="destinationIndex">Index of the first result.</param>
    /// <param name="length">Number of directions.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">A range does not fit its array.</exception>
    public static void TransformNormal(Vector2[] sourceArray, int sourceIndex, ref Matrix matrix, Vector2[] destinationArray, int destinationIndex, int length) =>
        VectorArrays.Map(sourceArray, sourceIndex, matrix, destinationArray, destinationIndex, length, TransformNormal);
}
