using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace URWPGSim2D.Hosting;

/// <summary>
/// The likely cause of a failed strategy compilation, when its errors show one the troubleshooting
/// table of docs/strategies.md explains: two strategy classes in one folder (the same type defined
/// twice: CS0101, with CS0111, CS0102 and CS0229 following from it), a part of the original's API
/// that is not provided (CS0117 or CS1061 on a type of the compatibility assembly, CS0234 in one of
/// its namespaces, CS0246 on a name of the original that is left out), or a Windows or user-interface
/// API (CS0234 in <c>System.Windows.Forms</c> or <c>Microsoft.Dss</c>, CS0246 or CS0103 on <c>Form</c> or <c>MessageBox</c>, CS1069). Each cause is one line: what is
/// wrong and what to do.
/// </summary>
internal static class CompileCause
{
    /// <summary>Namespaces of the original's API, as the compatibility assembly provides them.</summary>
    private static readonly string[] OriginalNamespaces = ["URWPGSim2D", "Microsoft.Xna"];

    /// <summary>Names of the original that exist only for its user interface or remoting and are not provided.</summary>
    private static readonly string[] OriginalOnly = ["IMission", "IDssSerializable"];

    /// <summary>Namespaces of Windows and user-interface APIs that do not exist here (Windows Forms, the original's DSS runtime).</summary>
    private static readonly string[] WindowsNamespaces = ["System.Windows.Forms", "Microsoft.Dss", "Microsoft.Ccr"];

    /// <summary>Type names of Windows Forms a strategy may use without its namespace in sight.</summary>
    private static readonly string[] WindowsNames = ["Form", "MessageBox"];

    /// <summary>The likely cause, one line without a trailing period, or null when the errors show none.</summary>
    /// <param name="compilation">The failed compilation.</param>
    /// <param name="errors">Its errors, in file and line order.</param>
    public static string? Find(Compilation compilation, IReadOnlyList<Diagnostic> errors)
    {
        return Duplicate(compilation, errors) ?? Original(compilation, errors) ?? Windows(compilation, errors);
    }

    // CS0101: a type defined twice (two strategies' Strategy classes); the files that define it.
    private static string? Duplicate(Compilation compilation, IReadOnlyList<Diagnostic> errors)
    {
        foreach (var d in errors)
        {
            if (d.Id != "CS0101" || Node(compilation, d)?.FirstAncestorOrSelf<BaseTypeDeclarationSyntax>() is not { } declaration)
            {
                continue;
            }

            var symbol = compilation.GetSemanticModel(declaration.SyntaxTree).GetDeclaredSymbol(declaration);
            if (symbol is null)
            {
                continue;
            }

            var files = symbol.DeclaringSyntaxReferences.Select(r => r.SyntaxTree.FilePath).Distinct(StringComparer.Ordinal).Order(StringComparer.Ordinal).ToList();
            string where = files.Count > 1 ? "in " + And(files) : "twice in " + files[0];
            return $"two strategy classes in one folder ({symbol.ToDisplayString()} is defined {where}); give each team its own folder";
        }

        return null;
    }

    // A member or type of the original's API that the compatibility assembly does not provide.
    private static string? Original(Compilation compilation, IReadOnlyList<Diagnostic> errors)
    {
        foreach (var d in errors)
        {
            string? name = d.Id switch
            {
                "CS0117" or "CS1061" => MissingMember(compilation, d),
                "CS0234" => MissingInNamespace(compilation, d, OriginalNamespaces),
                "CS0246" => Node(compilation, d) is SimpleNameSyntax simple && OriginalOnly.Contains(simple.Identifier.ValueText) ? simple.Identifier.ValueText : null,
                _ => null,
            };
            if (name is not null)
            {
                return $"{name} is a part of the original's API this simulator does not provide ({d.Id}); use the members docs/strategies.md lists, or report the missing one";
            }
        }

        return null;
    }

    // A Windows or user-interface API (Windows Forms, the original's DSS runtime).
    private static string? Windows(Compilation compilation, IReadOnlyList<Diagnostic> errors)
    {
        foreach (var d in errors)
        {
            string? name = d.Id switch
            {
                "CS0234" => MissingInNamespace(compilation, d, ["System", "Microsoft"]) is { } n && WindowsNamespaces.Any(w => w == n || w.StartsWith(n + ".", StringComparison.Ordinal) || n.StartsWith(w + ".", StringComparison.Ordinal)) ? n : null,
                "CS0246" or "CS0103" => Node(compilation, d) is SimpleNameSyntax simple && WindowsNames.Contains(simple.Identifier.ValueText) ? simple.Identifier.ValueText : null,
                "CS1069" => Node(compilation, d)?.ToString(),
                _ => null,
            };
            if (name is not null)
            {
                return $"{name} is a Windows or user-interface API, not available here ({d.Id}); remove the code that uses it";
            }
        }

        return null;
    }

    // CS0117/CS1061 on X.Name where X's type comes from the compatibility assembly: "Type.Name".
    private static string? MissingMember(Compilation compilation, Diagnostic d)
    {
        if (Node(compilation, d) is not { } node)
        {
            return null;
        }

        ExpressionSyntax? receiver = node.FirstAncestorOrSelf<MemberAccessExpressionSyntax>()?.Expression
            ?? node.FirstAncestorOrSelf<MemberBindingExpressionSyntax>()?.FirstAncestorOrSelf<ConditionalAccessExpressionSyntax>()?.Expression;
        if (receiver is null)
        {
            return null;
        }

        var model = compilation.GetSemanticModel(node.SyntaxTree);
        var type = model.GetTypeInfo(receiver).Type ?? model.GetSymbolInfo(receiver).Symbol as ITypeSymbol;
        if (type is null || type.ContainingAssembly?.Name != typeof(Compat.Adapter.OriginalStrategyAdapter).Assembly.GetName().Name)
        {
            return null;
        }

        string member = node is SimpleNameSyntax simple ? simple.Identifier.ValueText : node.ToString();
        return type.Name + "." + member;
    }

    // CS0234 "'Name' does not exist in the namespace 'N'" with N one of (or under) the given roots: "N.Name".
    private static string? MissingInNamespace(Compilation compilation, Diagnostic d, string[] roots)
    {
        (SyntaxNode? left, SimpleNameSyntax? name) = Node(compilation, d) switch
        {
            QualifiedNameSyntax q => (q.Left, q.Right),
            MemberAccessExpressionSyntax m => (m.Expression, m.Name),
            SimpleNameSyntax { Parent: QualifiedNameSyntax q } s when q.Right == s => (q.Left, s),
            SimpleNameSyntax { Parent: MemberAccessExpressionSyntax m } s when m.Name == s => (m.Expression, s),
            _ => (null, null),
        };
        if (left is null || name is null)
        {
            return null;
        }

        string space = left.ToString();
        bool under = roots.Any(r => space == r || space.StartsWith(r + ".", StringComparison.Ordinal));
        return under ? space + "." + name.Identifier.ValueText : null;
    }

    private static SyntaxNode? Node(Compilation compilation, Diagnostic d)
    {
        if (d.Location.SourceTree is not { } tree || !compilation.SyntaxTrees.Contains(tree))
        {
            return null;
        }

        return tree.GetRoot().FindNode(d.Location.SourceSpan, getInnermostNodeForTie: true);
    }

    private static string And(List<string> items) =>
        items.Count == 2 ? items[0] + " and " + items[1] : string.Join(", ", items.Take(items.Count - 1)) + " and " + items[^1];
}
