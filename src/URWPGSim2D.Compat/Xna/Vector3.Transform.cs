namespace Microsoft.Xna.Framework;

/// <summary>XNA 3.1's transforms of <see cref="Vector3"/> by a <see cref="Matrix"/> (row vector times matrix) or a <see cref="Quaternion"/>.</summary>
public partial struct Vector3
{
    /// <summary>Transforms a point: position·matrix with w = 1, no perspective divide (as XNA).</summary>
    /// <param name="position">The point.</param>
    /// <param name="matrix">The matrix.</param>
    /// <returns>The transformed point (the translation M41… applies).</returns>
    public static Vector3 Transform(Vector3 position, Matrix matrix) =>
        new((position.X * matrix.M11) + (position.Y * matrix.M21) + (position.Z * matrix.M31) + matrix.M41, (position.X * matrix.M12) + (position.Y * matrix.M22) + (position.Z * matrix.M32) + matrix.M42, (position.X * matrix.M13) + (position.Y * matrix.M23) + (position.Z * matrix.M33) + matrix.M43);

    /// <summary>The <c>ref</c> form of <see cref="Transform(Vector3, Matrix)"/>.</summary>
    /// <param name="position">The point.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="result">The transformed point.</param>
    public static void Transform(ref Vector3 position, ref Matrix matrix, out Vector3 result) => result = Transform(position, matrix);

    /// <summary>Transforms a direction: normal·matrix with w = 0 (the translation does not apply).</summary>
    /// <param name="normal">The direction.</param>
    /// <param name="matrix">The matrix.</param>
    /// <returns>The transformed direction.</returns>
    public static Vector3 TransformNormal(Vector3 normal, Matrix matrix) =>
        new((normal.X * matrix.M11) + (normal.Y * matrix.M21) + (normal.Z * matrix.M31), (normal.X * matrix.M12) + (normal.Y * matrix.M22) + (normal.Z * matrix.M32), (normal.X * matrix.M13) + (normal.Y * matrix.M23) + (normal.Z * matrix.M33));

    /// <summary>The <c>ref</c> form of <see cref="TransformNormal(Vector3, Matrix)"/>.</summary>
    /// <param name="normal">The direction.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="result">The transformed direction.</param>
    public static void TransformNormal(ref Vector3 normal, ref Matrix matrix, out Vector3 result) => result = TransformNormal(normal, matrix);

    /// <summary>Rotates a vector by a unit quaternion (q·v·q*).</summary>
    /// <param name="value">The vector.</param>
    /// <param name="rotation">The rotation.</param>
    /// <returns>The rotated vector.</returns>
    public static Vector3 Transform(Vector3 value, Quaternion rotation)
    {
        // v' = v + w·t + u × t with u the vector part and t = 2·(u × v): the rotation q·v·q* of a unit quaternion.
        var u = new Vector3(rotation.X, rotation.Y, rotation.Z);
        var t = Cross(u, value) * 2f;
        return value + (t * rotation.W) + Cross(u, t);
    }

    /// <summary>The <c>ref</c> form of <see cref="Transform(Vector3, Quaternion)"/>.</summary>
    /// <param name="value">The vector.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="result">The rotated vector.</param>
    public static void Transform(ref Vector3 value, ref Quaternion rotation, out Vector3 result) => result = Transform(value, rotation);

    /// <summary>Transforms every point of an array (<see cref="Transform(Vector3, Matrix)"/>) into another (or the same) array.</summary>
    /// <param name="sourceArray">The points.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go, at the same indices (at least as long as the source).</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">The destination is shorter than the source.</exception>
    public static void Transform(Vector3[] sourceArray, ref Matrix matrix, Vector3[] destinationArray) =>
        VectorArrays.Map(sourceArray, matrix, destinationArray, Transform);

    /// <summary>Transforms a range of points (<see cref="Transform(Vector3, Matrix)"/>) into a range of another (or the same) array.</summary>
    /// <param name="sourceArray">The points.</param>
    /// <param name="sourceIndex">First point to transform.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go.</param>
    /// <param name="destinationIndex">Index of the first result.</param>
    /// <param name="length">Number of points.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">A range does not fit its array.</exception>
    public static void Transform(Vector3[] sourceArray, int sourceIndex, ref Matrix matrix, Vector3[] destinationArray, int destinationIndex, int length) =>
        VectorArrays.Map(sourceArray, sourceIndex, matrix, destinationArray, destinationIndex, length, Transform);

    /// <summary>Rotates every vector of an array (<see cref="Transform(Vector3, Quaternion)"/>) into another (or the same) array.</summary>
    /// <param name="sourceArray">The vectors.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="destinationArray">Where the results go, at the same indices (at least as long as the source).</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">The destination is shorter than the source.</exception>
    public static void Transform(Vector3[] sourceArray, ref Quaternion rotation, Vector3[] destinationArray) =>
        VectorArrays.Map(sourceArray, rotation, destinationArray, Transform);

    /// <summary>Rotates a range of vectors (<see cref="Transform(Vector3, Quaternion)"/>) into a range of another (or the same) array.</summary>
    /// <param name="sourceArray">The vectors.</param>
    /// <param name="sourceIndex">First vector to rotate.</param>
    /// <param name="rotation">The rotation.</param>
    /// <param name="destinationArray">Where the results go.</param>
    /// <param name="destinationIndex">Index of the first result.</param>
    /// <param name="length">Number of vectors.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">A range does not fit its array.</exception>
    public static void Transform(Vector3[] sourceArray, int sourceIndex, ref Quaternion rotation, Vector3[] destinationArray, int destinationIndex, int length) =>
        VectorArrays.Map(sourceArray, sourceIndex, rotation, destinationArray, destinationIndex, length, Transform);

    /// <summary>Transforms every direction of an array (<see cref="TransformNormal(Vector3, Matrix)"/>) into another (or the same) array.</summary>
    /// <param name="sourceArray">The directions.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go, at the same indices (at least as long as the source).</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">The destination is shorter than the source.</exception>
    public static void TransformNormal(Vector3[] sourceArray, ref Matrix matrix, Vector3[] destinationArray) =>
        VectorArrays.Map(sourceArray, matrix, destinationArray, TransformNormal);

    /// <summary>Transforms a range of directions (<see cref="TransformNormal(Vector3, Matrix)"/>) into a range of another (or the same) array.</summary>
    /// <param name="sourceArray">The directions.</param>
    /// <param name="sourceIndex">First direction to transform.</param>
    /// <param name="matrix">The matrix.</param>
    /// <param name="destinationArray">Where the results go.</param>
    /// <param name="destinationIndex">Index of the first result.</param>
    /// <param name="length">Number of directions.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">A range does not fit its array.</exception>
    public static void TransformNormal(Vector3[] sourceArray, int sourceIndex, ref Matrix matrix, Vector3[] destinationArray, int destinationIndex, int length) =>
        VectorArrays.Map(sourceArray, sourceIndex, matrix, destinationArray, destinationIndex, length, TransformNormal);
}
