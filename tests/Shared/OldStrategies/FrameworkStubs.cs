namespace URWPGSim2D.Tests.OldStrategies;

/// <summary>
/// Sources of the .NET Framework 2.0 reference assemblies an old strategy was compiled against
/// (<c>mscorlib</c> and <c>System.Drawing</c> 2.0.0.0), reduced to what strategies and the original's API
/// use. Written for these tests; every member named here exists with the same signature in this
/// runtime (reached through its <c>mscorlib</c> and <c>System.Drawing</c> facades), so a DLL compiled
/// against them binds as one compiled against the real ones would.
/// </summary>
internal static class FrameworkStubs
{
    /// <summary>mscorlib 2.0.0.0.</summary>
    public const string Mscorlib = """
        [assembly: System.Reflection.AssemblyVersion("2.0.0.0")]
        namespace System
        {
            public class Object
            {
                public Object() { }
                public virtual string ToString() { return null; }
                public virtual bool Equals(object obj) { return false; }
                public virtual int GetHashCode() { return 0; }
                public Type GetType() { return null; }
                ~Object() { }
            }
            public abstract class ValueType { }
            public abstract class Enum : ValueType { }
            public struct Void { }
            public struct Boolean { }
            public struct Char { }
            public struct SByte { }
            public struct Byte { }
            public struct Int16 { }
            public struct UInt16 { }
            public struct Int32 { public const int MaxValue = 2147483647; public const int MinValue = -2147483648; public override string ToString() { return null; } }
            public struct UInt32 { }
            public struct Int64 { }
            public struct UInt64 { }
            public struct Single { public const float MaxValue = 3.40282347E+38f; public const float MinValue = -3.40282347E+38f; public override string ToString() { return null; } }
            public struct Double { }
            public struct IntPtr { }
            public struct UIntPtr { }
            public struct Nullable<T> where T : struct { }
            public struct RuntimeTypeHandle { }
            public struct RuntimeFieldHandle { }
            public struct RuntimeMethodHandle { }
            public sealed class String
            {
                public int Length { get { return 0; } }
                public static string Concat(object arg0, object arg1) { return null; }
                public static string Concat(string str0, string str1) { return null; }
                public static string Concat(string str0, string str1, string str2) { return null; }
                public static string Format(string format, object arg0) { return null; }
                public static bool operator ==(string a, string b) { return false; }
                public static bool operator !=(string a, string b) { return false; }
                public override bool Equals(object obj) { return false; }
                public override int GetHashCode() { return 0; }
            }
            public abstract class Array { public int Length { get { return 0; } } }
            public abstract class Delegate { }
            public abstract class MulticastDelegate : Delegate { }
            public abstract class Type
            {
                public static Type GetTypeFromHandle(RuntimeTypeHandle handle) { return null; }
                public abstract System.Reflection.Assembly Assembly { get; }
            }
            public abstract class Attribute { }
            public enum AttributeTargets { Assembly = 1, Class = 4, Struct = 8, Enum = 16, Method = 64, Field = 256, Interface = 1024, All = 32767 }
            [AttributeUsage(AttributeTargets.Class)]
            public sealed class AttributeUsageAttribute : Attribute
            {
                public AttributeUsageAttribute(AttributeTargets validOn) { }
                public bool AllowMultiple { get { return false; } set { } }
                public bool Inherited { get { return false; } set { } }
            }
            public sealed class ParamArrayAttribute : Attribute { }
            public sealed class SerializableAttribute : Attribute { }
            public sealed class FlagsAttribute : Attribute { }
            public class Exception { public Exception() { } public Exception(string message) { } }
            public class InvalidOperationException : Exception { public InvalidOperationException(string message) { } }
            public interface IDisposable { void Dispose(); }
            public interface ICloneable { object Clone(); }
            public abstract class MarshalByRefObject { public virtual object InitializeLifetimeService() { return null; } }
            public static class Math
            {
                public const double PI = 3.14159265358979323846;
                public static double Sqrt(double d) { return 0; }
                public static double Atan2(double y, double x) { return 0; }
                public static double Sin(double a) { return 0; }
                public static double Cos(double d) { return 0; }
                public static float Abs(float value) { return 0; }
                public static int Abs(int value) { return 0; }
                public static float Min(float val1, float val2) { return 0; }
                public static float Max(float val1, float val2) { return 0; }
                public static int Min(int val1, int val2) { return 0; }
                public static int Max(int val1, int val2) { return 0; }
            }
            public static class Convert
            {
                public static int ToInt32(object value) { return 0; }
                public static bool ToBoolean(object value) { return false; }
                public static float ToSingle(object value) { return 0; }
                public static string ToString(object value) { return null; }
            }
        }
        namespace System.Collections
        {
            public interface IEnumerable { IEnumerator GetEnumerator(); }
            public interface IEnumerator { bool MoveNext(); object Current { get; } void Reset(); }
            public interface ICollection : IEnumerable { }
            public interface IDictionary : ICollection { }
            public class Hashtable : IDictionary, System.ICloneable
            {
                public Hashtable() { }
                public virtual object this[object key] { get { return null; } set { } }
                public virtual int Count { get { return 0; } }
                public virtual bool ContainsKey(object key) { return false; }
                public virtual object Clone() { return null; }
                public virtual IEnumerator GetEnumerator() { return null; }
            }
        }
        namespace System.Collections.Generic
        {
            public interface IEnumerable<T> : System.Collections.IEnumerable { new IEnumerator<T> GetEnumerator(); }
            public interface IEnumerator<T> : System.IDisposable, System.Collections.IEnumerator { new T Current { get; } }
            public interface ICollection<T> : IEnumerable<T> { }
            public interface IList<T> : ICollection<T> { }
            public class List<T> : IList<T>
            {
                public List() { }
                public int Count { get { return 0; } }
                public T this[int index] { get { return default(T); } set { } }
                public void Add(T item) { }
                public void Clear() { }
                public T[] ToArray() { return null; }
                public Enumerator GetEnumerator() { return default(Enumerator); }
                IEnumerator<T> IEnumerable<T>.GetEnumerator() { return null; }
                System.Collections.IEnumerator System.Collections.IEnumerable.GetEnumerator() { return null; }
                public struct Enumerator : IEnumerator<T>
                {
                    public T Current { get { return default(T); } }
                    object System.Collections.IEnumerator.Current { get { return null; } }
                    public bool MoveNext() { return false; }
                    public void Dispose() { }
                    void System.Collections.IEnumerator.Reset() { }
                }
            }
        }
        namespace System.IO
        {
            public static class File
            {
                public static void AppendAllText(string path, string contents) { }
                public static string ReadAllText(string path) { return null; }
            }
        }
        namespace System.Resources
        {
            public class ResourceManager
            {
                public ResourceManager(string baseName, System.Reflection.Assembly assembly) { }
                public virtual string GetString(string name) { return null; }
            }
        }
        namespace System.Reflection
        {
            public abstract class Assembly { }
            [System.AttributeUsage(System.AttributeTargets.Class)]
            public sealed class DefaultMemberAttribute : System.Attribute { public DefaultMemberAttribute(string memberName) { } }
            [System.AttributeUsage(System.AttributeTargets.Assembly)]
            public sealed class AssemblyVersionAttribute : System.Attribute { public AssemblyVersionAttribute(string version) { } }
        }
        namespace System.Runtime.CompilerServices
        {
            public sealed class CompilationRelaxationsAttribute : System.Attribute { public CompilationRelaxationsAttribute(int relaxations) { } }
            public sealed class RuntimeCompatibilityAttribute : System.Attribute
            {
                public RuntimeCompatibilityAttribute() { }
                public bool WrapNonExceptionThrows { get { return false; } set { } }
            }
        }
        """;

    /// <summary>System.Drawing 2.0.0.0 (the colours and points of the original's API).</summary>
    public const string SystemDrawing = """
        [assembly: System.Reflection.AssemblyVersion("2.0.0.0")]
        namespace System.Drawing
        {
            public struct Color
            {
                public byte R { get { return 0; } }
                public byte G { get { return 0; } }
                public byte B { get { return 0; } }
                public static Color Red { get { return default(Color); } }
                public static Color Blue { get { return default(Color); } }
                public static Color FromArgb(int red, int green, int blue) { return default(Color); }
            }
            public struct Point
            {
                public Point(int x, int y) { }
                public int X { get { return 0; } set { } }
                public int Y { get { return 0; } set { } }
            }
        }
        """;
}
