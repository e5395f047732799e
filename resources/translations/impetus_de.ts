<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>GraphQuantity</name>
    <message>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>angle (rad)</source>
        <translation>Winkel (rad)</translation>
    </message>
    <message>
        <source>vx (m/s)</source>
        <translation>vx (m/s)</translation>
    </message>
    <message>
        <source>vy (m/s)</source>
        <translation>vy (m/s)</translation>
    </message>
    <message>
        <source>speed (m/s)</source>
        <translation>Geschwindigkeit (m/s)</translation>
    </message>
    <message>
        <source>ω (rad/s)</source>
        <translation>ω (rad/s)</translation>
    </message>
    <message>
        <source>px (kg·m/s)</source>
        <translation>px (kg·m/s)</translation>
    </message>
    <message>
        <source>py (kg·m/s)</source>
        <translation>py (kg·m/s)</translation>
    </message>
    <message>
        <source>kinetic energy (J)</source>
        <translation>kinetische Energie (J)</translation>
    </message>
    <message>
        <source>potential energy (J)</source>
        <translation>potentielle Energie (J)</translation>
    </message>
    <message>
        <source>kinetic + potential (J)</source>
        <translation>kinetisch + potentiell (J)</translation>
    </message>
    <message>
        <source>collisions</source>
        <translation>Kollisionen</translation>
    </message>
    <message>
        <source>world kinetic energy (J)</source>
        <translation>kinetische Energie der Welt (J)</translation>
    </message>
    <message>
        <source>world potential energy (J)</source>
        <translation>potentielle Energie der Welt (J)</translation>
    </message>
    <message>
        <source>world elastic energy (J)</source>
        <translation>elastische Energie der Welt (J)</translation>
    </message>
    <message>
        <source>world total energy (J)</source>
        <translation>Gesamtenergie der Welt (J)</translation>
    </message>
    <message>
        <source>world px (kg·m/s)</source>
        <translation>px der Welt (kg·m/s)</translation>
    </message>
    <message>
        <source>world py (kg·m/s)</source>
        <translation>py der Welt (kg·m/s)</translation>
    </message>
    <message>
        <source>world angular momentum (kg·m²/s)</source>
        <translation>Drehimpuls der Welt (kg·m²/s)</translation>
    </message>
    <message>
        <source>world collisions</source>
        <translation>Kollisionen der Welt</translation>
    </message>
</context>
<context>
    <name>RotationGesture</name>
    <message>
        <source>Rotate</source>
        <translation>Drehen</translation>
    </message>
</context>
<context>
    <name>Tool</name>
    <message>
        <source>box</source>
        <translation>Rechteck</translation>
    </message>
    <message>
        <source>Draw box</source>
        <translation>Rechteck zeichnen</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <source>Draw circle</source>
        <translation>Kreis zeichnen</translation>
    </message>
    <message>
        <source>ellipse</source>
        <translation>Ellipse</translation>
    </message>
    <message>
        <source>Draw ellipse</source>
        <translation>Ellipse zeichnen</translation>
    </message>
    <message>
        <source>Add pin</source>
        <translation>Gelenk hinzufügen</translation>
    </message>
    <message>
        <source>Add rod</source>
        <translation>Stange hinzufügen</translation>
    </message>
    <message>
        <source>Click on a body to pin it there: to the body under it, or to the world.</source>
        <translation>Auf einen Körper klicken, um ihn dort anzuheften: an den Körper darunter oder an die Welt.</translation>
    </message>
    <message>
        <source>Drag from a body to another body, or to a point in space, to add a rod.</source>
        <translation>Von einem Körper zu einem anderen Körper oder zu einem Punkt im Raum ziehen, um eine Stange hinzuzufügen.</translation>
    </message>
    <message>
        <source>a polygon needs at least 3 different corners</source>
        <translation>ein Polygon braucht mindestens 3 verschiedene Ecken</translation>
    </message>
    <message>
        <source>a corner is not a finite point</source>
        <translation>eine Ecke ist kein endlicher Punkt</translation>
    </message>
    <message>
        <source>two corners are at the same point</source>
        <translation>zwei Ecken liegen am selben Punkt</translation>
    </message>
    <message>
        <source>it is too small or flat to have an area</source>
        <translation>es ist zu klein oder zu flach, um eine Fläche zu haben</translation>
    </message>
    <message>
        <source>its edges cross each other</source>
        <translation>seine Kanten kreuzen sich</translation>
    </message>
    <message>
        <source>Cannot close the polygon: %1. Move or remove a corner (Backspace), or press Escape to give up.</source>
        <translation>Das Polygon lässt sich nicht schließen: %1. Eine Ecke verschieben oder entfernen (Rücktaste) oder mit Escape aufgeben.</translation>
    </message>
    <message>
        <source>polygon</source>
        <translation>Polygon</translation>
    </message>
    <message>
        <source>Draw polygon</source>
        <translation>Polygon zeichnen</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Nudge</source>
        <translation>Fein verschieben</translation>
    </message>
    <message>
        <source>Add spring</source>
        <translation>Feder hinzufügen</translation>
    </message>
    <message>
        <source>Drag from a body to another body, or to a point in space, to add a spring.</source>
        <translation>Von einem Körper zu einem anderen Körper oder zu einem Punkt im Raum ziehen, um eine Feder hinzuzufügen.</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Δx = %1 m, Δy = %2 m</source>
        <translation>Δx = %1 m, Δy = %2 m</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 (fixed)</source>
        <translation>%1 (fest)</translation>
    </message>
    <message>
        <source>x = %1 m, y = %2 m</source>
        <translation>x = %1 m, y = %2 m</translation>
    </message>
    <message>
        <source>vx = %1 m/s, vy = %2 m/s</source>
        <translation>vx = %1 m/s, vy = %2 m/s</translation>
    </message>
    <message>
        <source>speed = %1 m/s</source>
        <translation>Betrag der Geschwindigkeit = %1 m/s</translation>
    </message>
    <message>
        <source>angle = %1 rad (%2°), ω = %3 rad/s</source>
        <translation>Winkel = %1 rad (%2°), ω = %3 rad/s</translation>
    </message>
    <message>
        <source>p = (%1, %2) kg·m/s</source>
        <translation>p = (%1; %2) kg·m/s</translation>
    </message>
    <message>
        <source>K = %1 J, U = %2 J, K + U = %3 J</source>
        <translation>K = %1 J, U = %2 J, K + U = %3 J</translation>
    </message>
    <message>
        <source>collisions: %1, touching now</source>
        <translation>Stöße: %1, berührt gerade</translation>
    </message>
    <message>
        <source>collisions: %1</source>
        <translation>Stöße: %1</translation>
    </message>
</context>
<context>
    <name>impetus::app::App</name>
    <message>
        <source>--size must be WxH with both sides from 1 to %1 pixels, not “%2”</source>
        <translation>--size muss BxH sein, beide Seiten von 1 bis %1 Pixel, nicht „%2“</translation>
    </message>
    <message>
        <source>--run-for must be a number of seconds ≥ 0, not “%1”</source>
        <translation>--run-for muss eine Anzahl Sekunden ≥ 0 sein, nicht „%1“</translation>
    </message>
    <message>
        <source>--run-for %1 s is %2 steps, more than the %3 allowed</source>
        <translation>--run-for %1 s sind %2 Schritte, mehr als die erlaubten %3</translation>
    </message>
    <message>
        <source>the simulation produced a non-finite number: body “%1”, by t = %2 s</source>
        <translation>die Simulation hat eine nicht endliche Zahl ergeben: Körper „%1“, bis t = %2 s</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Impetus, a 2D physics lab for the classroom.</source>
        <translation>Impetus, ein 2D-Physiklabor für den Unterricht.</translation>
    </message>
    <message>
        <source>Render the canvas to the PNG file FILE and exit.</source>
        <translation>Die Simulationsfläche in die PNG-Datei DATEI zeichnen und beenden.</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>DATEI</translation>
    </message>
    <message>
        <source>With --screenshot: simulate SECONDS first (default 0).</source>
        <translation>Mit --screenshot: zuerst SEKUNDEN simulieren (Standard 0).</translation>
    </message>
    <message>
        <source>SECONDS</source>
        <translation>SEKUNDEN</translation>
    </message>
    <message>
        <source>With --screenshot: the image size in pixels (default 1280x720).</source>
        <translation>Mit --screenshot: die Bildgröße in Pixeln (Standard 1280x720).</translation>
    </message>
    <message>
        <source>WxH</source>
        <translation>BxH</translation>
    </message>
    <message>
        <source>The scene file to open (default: the example scene).</source>
        <translation>Die zu öffnende Szenendatei (Standard: die Beispielszene).</translation>
    </message>
    <message>
        <source>expected at most one scene file, got %1</source>
        <translation>höchstens eine Szenendatei erwartet, %1 erhalten</translation>
    </message>
    <message>
        <source>--run-for and --size need --screenshot</source>
        <translation>--run-for und --size brauchen --screenshot</translation>
    </message>
    <message>
        <source>Start the simulation as soon as the window opens.</source>
        <translation>Die Simulation starten, sobald das Fenster offen ist.</translation>
    </message>
    <message>
        <source>--run opens a window, --screenshot does not: give one of them</source>
        <translation>--run öffnet ein Fenster, --screenshot nicht: geben Sie nur eine der beiden an</translation>
    </message>
</context>
<context>
    <name>impetus::view</name>
    <message>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>impetus::view::Autosave</name>
    <message>
        <source>cannot write the autosave &apos;%1&apos;: %2</source>
        <translation>die automatische Sicherung „%1“ kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>%1: not a description of an autosave: %2</source>
        <translation>%1: keine Beschreibung einer automatischen Sicherung: %2</translation>
    </message>
    <message>
        <source>%1: cannot read it: %2</source>
        <translation>%1: nicht lesbar: %2</translation>
    </message>
    <message>
        <source>Restore Unsaved Work</source>
        <translation>Ungesicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <source>An autosave from %1 cannot be read and was not restored. It was kept in “%2”.</source>
        <translation>Eine automatische Sicherung vom %1 ist nicht lesbar und wurde nicht wiederhergestellt. Sie liegt in „%2“.</translation>
    </message>
    <message>
        <source>Impetus was not closed properly. Your work on “%1” was saved automatically at %2.</source>
        <translation>Impetus wurde nicht ordnungsgemäß beendet. Ihre Arbeit an „%1“ wurde am %2 automatisch gesichert.</translation>
    </message>
    <message>
        <source>Restore it? Discarding deletes the autosave.</source>
        <translation>Wiederherstellen? Verwerfen löscht die automatische Sicherung.</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellen</translation>
    </message>
</context>
<context>
    <name>impetus::view::CanvasInstruments</name>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>kg·m/s</source>
        <translation>kg·m/s</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>Gewichtskraft</translation>
    </message>
    <message>
        <source>springs</source>
        <translation>Federn</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>contact normal</source>
        <translation>Normalkraft</translation>
    </message>
    <message>
        <source>friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <source>joints</source>
        <translation>Gelenke</translation>
    </message>
    <message>
        <source>1 %1 = %2 m</source>
        <translation>1 %1 = %2 m</translation>
    </message>
    <message>
        <source>velocity: %1</source>
        <translation>Geschwindigkeit: %1</translation>
    </message>
    <message>
        <source>acceleration: %1</source>
        <translation>Beschleunigung: %1</translation>
    </message>
    <message>
        <source>net force: %1</source>
        <translation>Gesamtkraft: %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>momentum: %1</source>
        <translation>Impuls: %1</translation>
    </message>
</context>
<context>
    <name>impetus::view::CanvasView</name>
    <message>
        <source>Simulation canvas</source>
        <translation>Simulationsfläche</translation>
    </message>
    <message>
        <source>The bodies, springs and joints of the scene, in metres, y up</source>
        <translation>Die Körper, Federn und Gelenke der Szene, in Metern, y nach oben</translation>
    </message>
    <message>
        <source>%L1 m</source>
        <translation>%L1 m</translation>
    </message>
</context>
<context>
    <name>impetus::view::CollisionInspector</name>
    <message>
        <source>Pause the run to bring the log up to date.</source>
        <translation>Die Simulation anhalten, um das Protokoll zu aktualisieren.</translation>
    </message>
    <message>
        <source>No collisions yet. Run or step the scene, then pause.</source>
        <translation>Noch keine Stöße. Die Szene laufen lassen oder schrittweise weiterschalten, dann anhalten.</translation>
    </message>
    <message numerus="yes">
        <source>%n collision(s). Click one to see its impulse.</source>
        <translation>
            <numerusform>%n Stoß. Anklicken, um seinen Kraftstoß zu sehen.</numerusform>
            <numerusform>%n Stöße. Einen anklicken, um seinen Kraftstoß zu sehen.</numerusform>
        </translation>
    </message>
    <message>
        <source>t = %1 s: %2 and %3, impulse %4 N·s</source>
        <translation>t = %1 s: %2 und %3, Kraftstoß %4 N·s</translation>
    </message>
    <message>
        <source>&lt;h3&gt;%1 and %2 at t = %3 s&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;%1 und %2 bei t = %3 s&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Normal n = %1 (from %2 to %3). Total normal impulse this step, as logged: &lt;b&gt;%4 N·s&lt;/b&gt;; relative normal speed %5 m/s before, %6 m/s after the step.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normale n = %1 (von %2 zu %3). Gesamter Kraftstoß längs der Normalen in diesem Schritt, laut Protokoll: &lt;b&gt;%4 N·s&lt;/b&gt;; relative Normalgeschwindigkeit %5 m/s vor und %6 m/s nach dem Schritt.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;No impact: the bodies met slower than the restitution threshold (%1 m/s), or were already touching, so the contact forces alone stopped the approach. No bounce, e plays no part.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Kein Stoß: Die Körper trafen langsamer aufeinander als die Schwelle für die Stoßzahl (%1 m/s) oder berührten sich schon, daher haben allein die Kontaktkräfte die Annäherung gestoppt. Kein Abprall, e spielt keine Rolle.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h4&gt;Impact %1 of %2&lt;/h4&gt;</source>
        <translation>&lt;h4&gt;Stoß %1 von %2&lt;/h4&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;m&lt;sub&gt;A&lt;/sub&gt; = %1 kg, 1/I&lt;sub&gt;A&lt;/sub&gt; = %2 1/(kg·m²); m&lt;sub&gt;B&lt;/sub&gt; = %3 kg, 1/I&lt;sub&gt;B&lt;/sub&gt; = %4 1/(kg·m²); e = %5, μ = %6&lt;/p&gt;</source>
        <translation>&lt;p&gt;m&lt;sub&gt;A&lt;/sub&gt; = %1 kg, 1/I&lt;sub&gt;A&lt;/sub&gt; = %2 1/(kg·m²); m&lt;sub&gt;B&lt;/sub&gt; = %3 kg, 1/I&lt;sub&gt;B&lt;/sub&gt; = %4 1/(kg·m²); e = %5; μ = %6&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Point %1&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Punkt %1&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;r&lt;sub&gt;A&lt;/sub&gt; = %1 m, r&lt;sub&gt;B&lt;/sub&gt; = %2 m; r&lt;sub&gt;A&lt;/sub&gt;×n = %3 m, r&lt;sub&gt;B&lt;/sub&gt;×n = %4 m&lt;br&gt;relative normal speed before v&lt;sub&gt;n&lt;/sub&gt; = %5 m/s&lt;/p&gt;</source>
        <translation>&lt;p&gt;r&lt;sub&gt;A&lt;/sub&gt; = %1 m, r&lt;sub&gt;B&lt;/sub&gt; = %2 m; r&lt;sub&gt;A&lt;/sub&gt;×n = %3 m, r&lt;sub&gt;B&lt;/sub&gt;×n = %4 m&lt;br&gt;relative Normalgeschwindigkeit vorher v&lt;sub&gt;n&lt;/sub&gt; = %5 m/s&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; / (1/m&lt;sub&gt;A&lt;/sub&gt; + 1/m&lt;sub&gt;B&lt;/sub&gt; + (r&lt;sub&gt;A&lt;/sub&gt;×n)²/I&lt;sub&gt;A&lt;/sub&gt; + (r&lt;sub&gt;B&lt;/sub&gt;×n)²/I&lt;sub&gt;B&lt;/sub&gt;)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / (%3 + %4 + (%5)²·%6 + (%7)²·%8)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / %9 = &lt;b&gt;%10 N·s&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; / (1/m&lt;sub&gt;A&lt;/sub&gt; + 1/m&lt;sub&gt;B&lt;/sub&gt; + (r&lt;sub&gt;A&lt;/sub&gt;×n)²/I&lt;sub&gt;A&lt;/sub&gt; + (r&lt;sub&gt;B&lt;/sub&gt;×n)²/I&lt;sub&gt;B&lt;/sub&gt;)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / (%3 + %4 + (%5)²·%6 + (%7)²·%8)&lt;br&gt;&amp;nbsp;&amp;nbsp;= −(1 + %1)·(%2) / %9 = &lt;b&gt;%10 N·s&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;|v&lt;sub&gt;n&lt;/sub&gt;| is below the restitution threshold (%1 m/s): the impulse only stops the approach, e counts as 0.&lt;/p&gt;</source>
        <translation>&lt;p&gt;|v&lt;sub&gt;n&lt;/sub&gt;| liegt unter der Schwelle für die Stoßzahl (%1 m/s): Der Kraftstoß stoppt nur die Annäherung, e zählt als 0.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Two points struck at once: the engine solves K·j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; for both together, K = [[%1, %2], [%3, %4]] 1/kg, and applied &lt;b&gt;%5 N·s&lt;/b&gt; here (the formula above is this point alone).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Zwei Punkte gleichzeitig getroffen: Die Simulation löst K·j = −(1 + e)·v&lt;sub&gt;n&lt;/sub&gt; für beide zusammen, K = [[%1; %2]; [%3; %4]] 1/kg, und hat hier &lt;b&gt;%5 N·s&lt;/b&gt; aufgebracht (die Formel oben gilt für diesen Punkt allein).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;The engine applied %1 N·s.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Die Simulation hat %1 N·s aufgebracht.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Normal speed after: v&lt;sub&gt;n&lt;/sub&gt;′ = %1 m/s (−e·v&lt;sub&gt;n&lt;/sub&gt; = %2 m/s)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normalgeschwindigkeit danach: v&lt;sub&gt;n&lt;/sub&gt;′ = %1 m/s (−e·v&lt;sub&gt;n&lt;/sub&gt; = %2 m/s)&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Friction: tangential speed v&lt;sub&gt;t&lt;/sub&gt; = %1 m/s; stopping it needs −v&lt;sub&gt;t&lt;/sub&gt;/K&lt;sub&gt;t&lt;/sub&gt; = %2 N·s with K&lt;sub&gt;t&lt;/sub&gt; = %3 1/kg; the limit μ·j = %4 N·s; applied %5 N·s: &lt;b&gt;%6&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Reibung: Tangentialgeschwindigkeit v&lt;sub&gt;t&lt;/sub&gt; = %1 m/s; um sie zu stoppen, braucht es −v&lt;sub&gt;t&lt;/sub&gt;/K&lt;sub&gt;t&lt;/sub&gt; = %2 N·s mit K&lt;sub&gt;t&lt;/sub&gt; = %3 1/kg; die Grenze ist μ·j = %4 N·s; aufgebracht %5 N·s: &lt;b&gt;%6&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>it slid (friction at its limit)</source>
        <translation>Gleiten (Reibung an ihrer Grenze)</translation>
    </message>
    <message>
        <source>it stuck (sliding stopped)</source>
        <translation>Haften (das Gleiten wurde gestoppt)</translation>
    </message>
    <message>
        <source>&lt;p&gt;Momentum of the pair: %1 → %2 kg·m/s&lt;br&gt;Kinetic energy of the pair: %3 → %4 J (%5 J)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Impuls des Paars: %1 → %2 kg·m/s&lt;br&gt;Kinetische Energie des Paars: %3 → %4 J (%5 J)&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;A fixed body takes any momentum: the pair&apos;s momentum changes by the impulse.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Ein fester Körper nimmt jeden Impuls auf: Der Impuls des Paars ändert sich um den Kraftstoß.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <extracomment>A vector: its x and y. Where the decimal separator is a comma, separate them with a semicolon: (0,6; -0,8).</extracomment>
        <translation>(%1; %2)</translation>
    </message>
</context>
<context>
    <name>impetus::view::EnergyLedgerChart</name>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>energy (J)</source>
        <translation>Energie (J)</translation>
    </message>
    <message>
        <source>Kinetic</source>
        <translation>Kinetisch</translation>
    </message>
    <message>
        <source>Potential</source>
        <translation>Potentiell</translation>
    </message>
    <message>
        <source>Elastic</source>
        <translation>Elastisch</translation>
    </message>
    <message>
        <source>Impacts</source>
        <translation>Stöße</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>Spring damping</source>
        <translation>Federdämpfung</translation>
    </message>
    <message>
        <source>Soft damping</source>
        <translation>Dämpfung (weich)</translation>
    </message>
    <message>
        <source>Joints</source>
        <translation>Gelenke</translation>
    </message>
    <message>
        <source>Position correction</source>
        <translation>Lagekorrektur</translation>
    </message>
    <message>
        <source>Drift</source>
        <translation>Drift</translation>
    </message>
    <message>
        <source>Run the simulation to fill the energy ledger.</source>
        <translation>Die Simulation laufen lassen, um die Energiebilanz zu füllen.</translation>
    </message>
    <message>
        <source>Start %1 J = now %2 J + losses %3 J (off by %4 J); drift %5 J</source>
        <translation>Anfang %1 J = jetzt %2 J + Verluste %3 J (Abweichung %4 J); Drift %5 J</translation>
    </message>
</context>
<context>
    <name>impetus::view::Examples</name>
    <message>
        <source>Billiards break</source>
        <translation>Billard-Anstoß</translation>
    </message>
    <message>
        <source>Box stack and overhang</source>
        <translation>Kistenstapel mit Überhang</translation>
    </message>
    <message>
        <source>Default scene</source>
        <translation>Standardszene</translation>
    </message>
    <message>
        <source>Block on an incline</source>
        <translation>Klotz auf der schiefen Ebene</translation>
    </message>
    <message>
        <source>Newton&apos;s cradle</source>
        <translation>Newtons Wiege</translation>
    </message>
    <message>
        <source>Pendulum</source>
        <translation>Pendel</translation>
    </message>
    <message>
        <source>Projectile over the ground</source>
        <translation>Wurf über dem Boden</translation>
    </message>
    <message>
        <source>Pyramid</source>
        <translation>Pyramide</translation>
    </message>
    <message>
        <source>Soft bodies: rigid and soft side by side</source>
        <translation>Weiche Körper: starr und weich nebeneinander</translation>
    </message>
    <message>
        <source>Spaceship and asteroids</source>
        <translation>Raumschiff und Asteroiden</translation>
    </message>
    <message>
        <source>Chain of springs</source>
        <translation>Federkette</translation>
    </message>
    <message>
        <source>Lesson: momentum in a cart crash</source>
        <translation>Lektion: Impuls beim Zusammenstoß zweier Wagen</translation>
    </message>
    <message>
        <source>Lesson: friction on an incline</source>
        <translation>Lektion: Reibung auf der schiefen Ebene</translation>
    </message>
    <message>
        <source>Lesson: pendulum period and length</source>
        <translation>Lektion: Periode und Länge des Pendels</translation>
    </message>
    <message>
        <source>Mass on a spring</source>
        <translation>Masse an einer Feder</translation>
    </message>
    <message>
        <source>Lesson: spring period and stiffness</source>
        <translation>Lektion: Periode und Federkonstante einer Feder</translation>
    </message>
    <message>
        <source>Lesson: tuning a pendulum</source>
        <translation>Lektion: ein Pendel abstimmen</translation>
    </message>
</context>
<context>
    <name>impetus::view::GraphPanel</name>
    <message>
        <source>Graph</source>
        <translation>Diagramm</translation>
    </message>
    <message>
        <source>Body plotted</source>
        <translation>Dargestellter Körper</translation>
    </message>
    <message>
        <source>Quantity on the vertical axis</source>
        <translation>Größe auf der senkrechten Achse</translation>
    </message>
    <message>
        <source>Quantity on the horizontal axis</source>
        <translation>Größe auf der waagrechten Achse</translation>
    </message>
    <message>
        <source>Value under the cursor</source>
        <translation>Wert unter dem Mauszeiger</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Als CSV exportieren…</translation>
    </message>
    <message>
        <source>Save every recorded step as a table (time, body and the plotted quantities)</source>
        <translation>Jeden aufgezeichneten Schritt als Tabelle speichern (Zeit, Körper und die dargestellten Größen)</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>Als PNG exportieren…</translation>
    </message>
    <message>
        <source>Save the graph as a picture</source>
        <translation>Das Diagramm als Bild speichern</translation>
    </message>
    <message>
        <source>against</source>
        <translation>gegen</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <source>%1 against %2 of %3</source>
        <translation>%1 gegen %2 von %3</translation>
    </message>
    <message>
        <source>%1 = %2, %3 = %4</source>
        <translation>%1 = %2; %3 = %4</translation>
    </message>
    <message>
        <source>Cannot write “%1”: %2</source>
        <translation>„%1“ lässt sich nicht schreiben: %2</translation>
    </message>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>Das Bild „%1“ lässt sich nicht schreiben.</translation>
    </message>
    <message>
        <source>Export Graph Data</source>
        <translation>Diagrammdaten exportieren</translation>
    </message>
    <message>
        <source>CSV tables (*.csv);;All files (*)</source>
        <translation>CSV-Tabellen (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
    <message>
        <source>Export Graph Picture</source>
        <translation>Diagramm als Bild exportieren</translation>
    </message>
    <message>
        <source>PNG pictures (*.png);;All files (*)</source>
        <translation>PNG-Bilder (*.png);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Drag a box over the plot to zoom in on it; right-click to see everything again</source>
        <translation>Ziehen Sie ein Rechteck über das Diagramm, um es zu vergrößern; Rechtsklick zeigt wieder alles</translation>
    </message>
</context>
<context>
    <name>impetus::view::IntegratorGhosts</name>
    <message>
        <source>Explicit Euler</source>
        <translation>Explizites Euler-Verfahren</translation>
    </message>
    <message>
        <source>Semi-implicit Euler</source>
        <translation>Halbimplizites Euler-Verfahren</translation>
    </message>
    <message>
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <source>1/%1 s</source>
        <translation>1/%1 s</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Ghosts, h = %1</source>
        <translation>Geister, h = %1</translation>
    </message>
</context>
<context>
    <name>impetus::view::IntegratorGhostsPanel</name>
    <message>
        <source>Energy error</source>
        <translation>Energiefehler</translation>
    </message>
    <message>
        <source>Position error</source>
        <translation>Positionsfehler</translation>
    </message>
    <message>
        <source>Energy error: (E − E₀)/|E₀|. Position error: the largest distance of a body from the textbook solution.</source>
        <translation>Energiefehler: (E − E₀)/|E₀|. Positionsfehler: der größte Abstand eines Körpers von der Lehrbuchlösung.</translation>
    </message>
    <message>
        <source>Ghosts&apos; time step h:</source>
        <translation>Zeitschritt h der Geister:</translation>
    </message>
    <message>
        <source>Ghosts&apos; time step</source>
        <translation>Zeitschritt der Geister</translation>
    </message>
    <message>
        <source>The ghosts&apos; fixed time step, from 1/1000 s (left) to 1/30 s (right)</source>
        <translation>Der feste Zeitschritt der Geister, von 1/1000 s (links) bis 1/30 s (rechts)</translation>
    </message>
    <message>
        <source>Largest position error in %1 s against the time step</source>
        <translation>Größter Positionsfehler in %1 s über dem Zeitschritt</translation>
    </message>
    <message>
        <source>time step h (s)</source>
        <translation>Zeitschritt h (s)</translation>
    </message>
    <message>
        <source>position error (m)</source>
        <translation>Positionsfehler (m)</translation>
    </message>
    <message>
        <source>ghosts&apos; h</source>
        <translation>h der Geister</translation>
    </message>
    <message>
        <source>Analytic solution: free flight, x = x₀ + v₀t + ½gt², until the first contact.</source>
        <translation>Analytische Lösung: freier Flug, x = x₀ + v₀t + ½gt², bis zum ersten Kontakt.</translation>
    </message>
    <message>
        <source>Analytic solution: a mass on a spring, x = x_eq + (x₀ − x_eq)·cos ωt + (v₀/ω)·sin ωt, ω = √(k/m).</source>
        <translation>Analytische Lösung: eine Masse an einer Feder, x = x_eq + (x₀ − x_eq)·cos ωt + (v₀/ω)·sin ωt, ω = √(k/m).</translation>
    </message>
    <message>
        <source>Analytic solution: a pendulum at any amplitude, sin(θ/2) = k·sn(ω₀t + u₀, k), ω₀ = √(g/L), until the first contact.</source>
        <translation>Analytische Lösung: ein Pendel bei beliebiger Amplitude, sin(θ/2) = k·sn(ω₀t + u₀, k), ω₀ = √(g/L), bis zum ersten Kontakt.</translation>
    </message>
    <message>
        <source>No analytic solution for this scene: only the energy errors can be compared.</source>
        <translation>Keine analytische Lösung für diese Szene: Nur die Energiefehler lassen sich vergleichen.</translation>
    </message>
    <message>
        <source>Bodies held by joints move by semi-implicit Euler whichever integrator is chosen, so their ghosts lie on one another.</source>
        <translation>Körper, die von Gelenken gehalten werden, bewegen sich unabhängig vom gewählten Integrator nach dem halbimpliziten Euler-Verfahren, daher liegen ihre Geister übereinander.</translation>
    </message>
    <message>
        <source>diverged at t = %1 s</source>
        <translation>divergiert bei t = %1 s</translation>
    </message>
    <message>
        <source>diverged</source>
        <translation>divergiert</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>no analytic solution after a contact</source>
        <translation>keine analytische Lösung nach einem Kontakt</translation>
    </message>
    <message>
        <source>no analytic solution</source>
        <translation>keine analytische Lösung</translation>
    </message>
    <message>
        <source>Ghosts at t = %1 s after their start: n = %2 steps of h = %3%4</source>
        <translation>Geister bei t = %1 s nach ihrem Start: n = %2 Schritte zu h = %3%4</translation>
    </message>
    <message>
        <source> (catching up)</source>
        <translation> (holen auf)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 exact to rounding</source>
        <translation>%1 bis auf Rundung exakt</translation>
    </message>
    <message>
        <source>No analytic solution for this scene: no error to plot.</source>
        <translation>Keine analytische Lösung für diese Szene: kein Fehler darzustellen.</translation>
    </message>
    <message>
        <source>Fitted slopes (the method&apos;s order): %1</source>
        <translation>Angepasste Steigungen (die Ordnung des Verfahrens): %1</translation>
    </message>
    <message>
        <source>, </source>
        <translation>; </translation>
    </message>
    <message>
        <source>Integrator Ghosts</source>
        <translation>Geister der Integratoren</translation>
    </message>
    <message>
        <source>Compare &amp;Integrators</source>
        <translation>&amp;Integratoren vergleichen</translation>
    </message>
    <message>
        <source>Run the scene under explicit Euler, semi-implicit Euler and RK4 beside the real run, drawn as ghosts, with their errors</source>
        <translation>Die Szene neben dem echten Lauf mit explizitem Euler-Verfahren, halbimplizitem Euler-Verfahren und RK4 laufen lassen, als Geister gezeichnet, mit ihren Fehlern</translation>
    </message>
</context>
<context>
    <name>impetus::view::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>The language changes the next time Impetus starts.</source>
        <translation>Die Sprache wechselt beim nächsten Start von Impetus.</translation>
    </message>
    <message>
        <source>System Language</source>
        <translation>Systemsprache</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonDock</name>
    <message>
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <source>Lesson (editing)</source>
        <translation>Lektion (in Bearbeitung)</translation>
    </message>
    <message>
        <source>&amp;Lesson</source>
        <translation>&amp;Lektion</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>Lift the lesson&apos;s locks and write its title, instructions, locks and questions</source>
        <translation>Die Sperren der Lektion aufheben und Titel, Anleitung, Sperren und Fragen bearbeiten</translation>
    </message>
    <message>
        <source>Create lesson</source>
        <translation>Lektion anlegen</translation>
    </message>
    <message>
        <source>&amp;Remove Lesson</source>
        <translation>Lektion &amp;entfernen</translation>
    </message>
    <message>
        <source>Take the lesson out of the scene: no locks, no questions</source>
        <translation>Die Lektion aus der Szene entfernen: keine Sperren, keine Fragen</translation>
    </message>
    <message>
        <source>Remove lesson</source>
        <translation>Lektion entfernen</translation>
    </message>
    <message>
        <source>Lesson &amp;Panel</source>
        <translation>Lektions&amp;leiste</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonEditor</name>
    <message>
        <source>Lesson editor</source>
        <translation>Lektionseditor</translation>
    </message>
    <message>
        <source>Lesson title</source>
        <translation>Titel der Lektion</translation>
    </message>
    <message>
        <source>&amp;Title</source>
        <translation>&amp;Titel</translation>
    </message>
    <message>
        <source>Instructions</source>
        <translation>Anleitung</translation>
    </message>
    <message>
        <source>Plain text or simple Markdown: **bold**, *italic*, lists</source>
        <translation>Einfacher Text oder einfaches Markdown: **fett**, *kursiv*, Listen</translation>
    </message>
    <message>
        <source>What students should do; **bold**, *italic* and lists work</source>
        <translation>Was die Schülerinnen und Schüler tun sollen; **fett**, *kursiv* und Listen gehen</translation>
    </message>
    <message>
        <source>&amp;Instructions</source>
        <translation>&amp;Anleitung</translation>
    </message>
    <message>
        <source>Students may change (ticked; everything else is locked):</source>
        <translation>Änderbar für Schülerinnen und Schüler (angehakt; alles andere ist gesperrt):</translation>
    </message>
    <message>
        <source>What students may change</source>
        <translation>Was Schülerinnen und Schüler ändern dürfen</translation>
    </message>
    <message>
        <source>&amp;Questions</source>
        <translation>&amp;Fragen</translation>
    </message>
    <message>
        <source>Questions</source>
        <translation>Fragen</translation>
    </message>
    <message>
        <source>Question</source>
        <translation>Frage</translation>
    </message>
    <message>
        <source>Answer</source>
        <translation>Antwort</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Tolerance (±)</source>
        <translation>Toleranz (±)</translation>
    </message>
    <message>
        <source>Add Question</source>
        <translation>Frage hinzufügen</translation>
    </message>
    <message>
        <source>Remove Question</source>
        <translation>Frage entfernen</translation>
    </message>
    <message>
        <source>Remove the current question</source>
        <translation>Die aktuelle Frage entfernen</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>World settings</source>
        <translation>Welteinstellungen</translation>
    </message>
    <message>
        <source>A lesson needs a title.</source>
        <translation>Eine Lektion braucht einen Titel.</translation>
    </message>
    <message>
        <source>Change lesson title</source>
        <translation>Titel der Lektion ändern</translation>
    </message>
    <message>
        <source>Change lesson instructions</source>
        <translation>Anleitung der Lektion ändern</translation>
    </message>
    <message>
        <source>Change which world settings students may change</source>
        <translation>Ändern, welche Welteinstellungen änderbar sind</translation>
    </message>
    <message>
        <source>Change what students may change of “%1”</source>
        <translation>Ändern, was an „%1“ änderbar ist</translation>
    </message>
    <message>
        <source>A question needs a prompt.</source>
        <translation>Eine Frage braucht einen Fragetext.</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number.</source>
        <translation>%1: „%2“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>Tolerance must be greater than 0 (got %1).</source>
        <translation>Die Toleranz muss größer als 0 sein (eingegeben: %1).</translation>
    </message>
    <message>
        <source>Edit question %1</source>
        <translation>Frage %1 bearbeiten</translation>
    </message>
    <message>
        <source>New question</source>
        <translation>Neue Frage</translation>
    </message>
    <message>
        <source>Add question</source>
        <translation>Frage hinzufügen</translation>
    </message>
    <message>
        <source>Remove question %1</source>
        <translation>Frage %1 entfernen</translation>
    </message>
    <message>
        <source>the world</source>
        <translation>der Welt</translation>
    </message>
    <message>
        <source>Spring %1 (%2 to %3)</source>
        <translation>Feder %1 (zwischen %2 und %3)</translation>
    </message>
    <message>
        <source>Change what students may change of spring %1</source>
        <translation>Ändern, was an Feder %1 änderbar ist</translation>
    </message>
    <message>
        <source>Pin %1 (%2 to %3)</source>
        <translation>Gelenk %1 (zwischen %2 und %3)</translation>
    </message>
    <message>
        <source>Rod %1 (%2 to %3)</source>
        <translation>Stange %1 (zwischen %2 und %3)</translation>
    </message>
    <message>
        <source>Change what students may change of joint %1</source>
        <translation>Ändern, was an Gelenk %1 änderbar ist</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonPanel</name>
    <message>
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <source>Lesson title</source>
        <translation>Titel der Lektion</translation>
    </message>
    <message>
        <source>Instructions</source>
        <translation>Anleitung</translation>
    </message>
    <message>
        <source>What you may change</source>
        <translation>Was änderbar ist</translation>
    </message>
    <message>
        <source>No lesson</source>
        <translation>Keine Lektion</translation>
    </message>
    <message>
        <source>This scene has no lesson. A teacher can write one with Lesson › Edit.</source>
        <translation>Diese Szene hat keine Lektion. Eine Lehrkraft kann mit Lektion › Bearbeiten eine schreiben.</translation>
    </message>
    <message>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source>Answer to question %1</source>
        <translation>Antwort auf Frage %1</translation>
    </message>
    <message>
        <source>your answer</source>
        <translation>deine Antwort</translation>
    </message>
    <message>
        <source>Unit: %1</source>
        <translation>Einheit: %1</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Prüfen</translation>
    </message>
    <message>
        <source>Check answer %1</source>
        <translation>Antwort %1 prüfen</translation>
    </message>
    <message>
        <source>Verdict on answer %1</source>
        <translation>Bewertung der Antwort %1</translation>
    </message>
    <message>
        <source>Type your answer first.</source>
        <translation>Zuerst eine Antwort eingeben.</translation>
    </message>
    <message>
        <source>“%1” is not a number.</source>
        <translation>„%1“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>Right! You are %1 off; up to %2 counts as right.</source>
        <translation>Richtig! Die Abweichung ist %1; bis %2 gilt als richtig.</translation>
    </message>
    <message>
        <source>Wrong: %1 too high (up to %2 off counts as right).</source>
        <translation>Falsch: %1 zu hoch (bis %2 Abweichung gilt als richtig).</translation>
    </message>
    <message>
        <source>Wrong: %1 too low (up to %2 off counts as right).</source>
        <translation>Falsch: %1 zu niedrig (bis %2 Abweichung gilt als richtig).</translation>
    </message>
    <message>
        <source>Lesson › Edit is on: nothing is locked.</source>
        <translation>Lektion › Bearbeiten ist an: nichts ist gesperrt.</translation>
    </message>
    <message>
        <source>“%1”: %2</source>
        <translation>„%1“: %2</translation>
    </message>
    <message>
        <source>world: %1</source>
        <translation>Welt: %1</translation>
    </message>
    <message>
        <source>Everything in this scene is locked by the lesson.</source>
        <translation>Alles in dieser Szene ist von der Lektion gesperrt.</translation>
    </message>
    <message>
        <source>You may change %1. Everything else is locked by the lesson.</source>
        <translation>Änderbar: %1. Alles andere ist von der Lektion gesperrt.</translation>
    </message>
    <message>
        <source>spring %1: %2</source>
        <translation>Feder %1: %2</translation>
    </message>
    <message>
        <source>joint %1: %2</source>
        <translation>Gelenk %1: %2</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonSession</name>
    <message>
        <source>Locked by the lesson: the %1 of “%2” can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: „%2“ (%1) lässt sich nicht ändern.</translation>
    </message>
    <message>
        <source>Locked by the lesson: the %1 can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: diese Einstellung (%1) lässt sich nicht ändern.</translation>
    </message>
    <message>
        <source>Locked by the lesson: “%1” can&apos;t be turned.</source>
        <translation>Von der Lektion gesperrt: „%1“ lässt sich nicht drehen.</translation>
    </message>
    <message>
        <source>Locked by the lesson: “%1” can&apos;t be moved.</source>
        <translation>Von der Lektion gesperrt: „%1“ lässt sich nicht verschieben.</translation>
    </message>
    <message>
        <source>Locked by the lesson: nothing can be deleted.</source>
        <translation>Von der Lektion gesperrt: nichts lässt sich löschen.</translation>
    </message>
    <message>
        <source>Locked by the lesson: new bodies, springs and joints can&apos;t be added.</source>
        <translation>Von der Lektion gesperrt: neue Körper, Federn und Gelenke lassen sich nicht hinzufügen.</translation>
    </message>
    <message>
        <source>Locked by the lesson: this body can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: dieser Körper lässt sich nicht ändern.</translation>
    </message>
    <message>
        <source>Locked by the lesson. You may change its %1.</source>
        <translation>Von der Lektion gesperrt. Änderbar: %1.</translation>
    </message>
    <message>
        <source>Locked by the lesson: the world settings can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: die Welteinstellungen lassen sich nicht ändern.</translation>
    </message>
    <message>
        <source>Locked by the lesson. You may change the %1.</source>
        <translation>Von der Lektion gesperrt. Änderbar: %1.</translation>
    </message>
    <message>
        <source>Locked by the lesson: the %1 of spring %2 can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: Feder %2 (%1) lässt sich nicht ändern.</translation>
    </message>
    <message>
        <source>Locked by the lesson: spring %1 can&apos;t be joined to other bodies.</source>
        <translation>Von der Lektion gesperrt: Feder %1 lässt sich nicht an andere Körper hängen.</translation>
    </message>
    <message>
        <source>Locked by the lesson: this spring can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: diese Feder lässt sich nicht ändern.</translation>
    </message>
    <message>
        <source>Locked by the lesson: the %1 of joint %2 can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: Gelenk %2 (%1) lässt sich nicht ändern.</translation>
    </message>
    <message>
        <source>Locked by the lesson: joint %1 can&apos;t be changed to another type or to other bodies.</source>
        <translation>Von der Lektion gesperrt: Gelenk %1 lässt sich nicht in eine andere Art ändern oder an andere Körper hängen.</translation>
    </message>
    <message>
        <source>Locked by the lesson: this joint can&apos;t be changed.</source>
        <translation>Von der Lektion gesperrt: dieses Gelenk lässt sich nicht ändern.</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>Drehpunkt</translation>
    </message>
</context>
<context>
    <name>impetus::view::LessonText</name>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>angular velocity</source>
        <translation>Winkelgeschwindigkeit</translation>
    </message>
    <message>
        <source>mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <source>restitution</source>
        <translation>Stoßzahl</translation>
    </message>
    <message>
        <source>friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <source>fixed</source>
        <translation>fest</translation>
    </message>
    <message>
        <source>colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <source>soft mode</source>
        <translation>weicher Modus</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>stiffness</source>
        <translation>Federkonstante</translation>
    </message>
    <message>
        <source>damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>rest length</source>
        <translation>Ruhelänge</translation>
    </message>
    <message>
        <source>anchors</source>
        <translation>Befestigungspunkte</translation>
    </message>
</context>
<context>
    <name>impetus::view::MainWindow</name>
    <message>
        <source>Impetus main window</source>
        <translation>Impetus-Hauptfenster</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>Start an empty scene</source>
        <translation>Eine leere Szene beginnen</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open a scene file</source>
        <translation>Eine Szenendatei öffnen</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save the scene to its file</source>
        <translation>Die Szene in ihre Datei speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Save the scene to a new file</source>
        <translation>Die Szene in eine neue Datei speichern</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Delete the selection, and the springs and joints on deleted bodies</source>
        <translation>Die Auswahl löschen, samt den Federn und Gelenken an gelöschten Körpern</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>&amp;Alles auswählen</translation>
    </message>
    <message>
        <source>&amp;Snap to Grid</source>
        <translation>Am &amp;Raster einrasten</translation>
    </message>
    <message>
        <source>Place and move points on the grid lines&apos; crossings</source>
        <translation>Punkte auf die Kreuzungen der Rasterlinien setzen und verschieben</translation>
    </message>
    <message>
        <source>Show Soft-Body &amp;Ellipses</source>
        <translation>&amp;Ellipsen weicher Körper zeigen</translation>
    </message>
    <message>
        <source>Draw the small ellipses a soft body is made of</source>
        <translation>Die kleinen Ellipsen zeichnen, aus denen ein weicher Körper besteht</translation>
    </message>
    <message>
        <source>Show Soft-Body S&amp;train</source>
        <translation>&amp;Dehnung weicher Körper zeigen</translation>
    </message>
    <message>
        <source>Draw a soft body&apos;s springs coloured by strain: blue compressed, grey at rest, red stretched</source>
        <translation>Die Federn eines weichen Körpers nach Dehnung gefärbt zeichnen: blau gestaucht, grau in Ruhe, rot gedehnt</translation>
    </message>
    <message>
        <source>&amp;Frame Scene</source>
        <translation>&amp;Ganze Szene zeigen</translation>
    </message>
    <message>
        <source>Zoom to show every body</source>
        <translation>So zoomen, dass alle Körper zu sehen sind</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Run the simulation (Space)</source>
        <translation>Die Simulation laufen lassen (Leertaste)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Advance one time step (→)</source>
        <translation>Einen Zeitschritt weiter (→)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Go back to the state at the last Play (R)</source>
        <translation>Zum Zustand beim letzten Start zurückkehren (R)</translation>
    </message>
    <message>
        <source>Select</source>
        <translation>Auswählen</translation>
    </message>
    <message>
        <source>Select, move (drag) and nudge (arrow keys); Ctrl+drag turns</source>
        <translation>Auswählen, verschieben (ziehen) und fein verschieben (Pfeiltasten); Strg+Ziehen dreht</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Drehen</translation>
    </message>
    <message>
        <source>Drag to turn a body or the selection about its centre</source>
        <translation>Ziehen, um einen Körper oder die Auswahl um seine Mitte zu drehen</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polygon</translation>
    </message>
    <message>
        <source>Click the corners; click the first one, press Enter or double-click to close</source>
        <translation>Die Ecken anklicken; zum Schließen die erste anklicken, Eingabe drücken oder doppelklicken</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Rechteck</translation>
    </message>
    <message>
        <source>Drag from corner to corner</source>
        <translation>Von Ecke zu Ecke ziehen</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <source>Drag from the centre out</source>
        <translation>Von der Mitte nach außen ziehen</translation>
    </message>
    <message>
        <source>Ellipse</source>
        <translation>Ellipse</translation>
    </message>
    <message>
        <source>Drag out its bounding box</source>
        <translation>Das umgebende Rechteck aufziehen</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Feder</translation>
    </message>
    <message>
        <source>Drag from a body to another body or to a point</source>
        <translation>Von einem Körper zu einem anderen Körper oder zu einem Punkt ziehen</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Click on a body to hinge it to the body below or the world</source>
        <translation>Auf einen Körper klicken, um ihn drehbar an den Körper darunter oder an die Welt zu heften</translation>
    </message>
    <message>
        <source>Rod</source>
        <translation>Stange</translation>
    </message>
    <message>
        <source>%1 (%2): %3</source>
        <translation>%1 (%2): %3</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Compare Soft with Rigid…</source>
        <translation>Weich mit starr &amp;vergleichen…</translation>
    </message>
    <message>
        <source>Run the selected soft body rigid and soft for a few seconds and show how far apart they drift</source>
        <translation>Den ausgewählten weichen Körper einige Sekunden lang starr und weich laufen lassen und zeigen, wie weit die beiden auseinanderdriften</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>Beisp&amp;iele</translation>
    </message>
    <message>
        <source>Run controls</source>
        <translation>Ablaufsteuerung</translation>
    </message>
    <message>
        <source>Play or pause</source>
        <translation>Starten oder anhalten</translation>
    </message>
    <message>
        <source>Step once</source>
        <translation>Einen Schritt weiter</translation>
    </message>
    <message>
        <source>Reset to the last Play</source>
        <translation>Auf den letzten Start zurücksetzen</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Tempo:</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>Simulation speed</source>
        <translation>Simulationstempo</translation>
    </message>
    <message>
        <source>Simulated seconds per real second</source>
        <translation>Simulierte Sekunden pro echter Sekunde</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>Drawing tools</source>
        <translation>Zeichenwerkzeuge</translation>
    </message>
    <message>
        <source>%1 tool</source>
        <translation>Werkzeug %1</translation>
    </message>
    <message>
        <source>Attributes</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Simulated time</source>
        <translation>Simulierte Zeit</translation>
    </message>
    <message>
        <source>Kinetic, potential and elastic energy</source>
        <translation>Kinetische, potentielle und elastische Energie</translation>
    </message>
    <message>
        <source>Kinetic energy K, gravitational potential energy U (from y = 0) and elastic energy of the springs</source>
        <translation>Kinetische Energie K, potentielle Energie U im Schwerefeld (ab y = 0) und Spannenergie der Federn</translation>
    </message>
    <message>
        <source>Total energy</source>
        <translation>Gesamtenergie</translation>
    </message>
    <message>
        <source>Total momentum</source>
        <translation>Gesamtimpuls</translation>
    </message>
    <message>
        <source>Collision count</source>
        <translation>Anzahl der Stöße</translation>
    </message>
    <message>
        <source>Soft bodies</source>
        <translation>Weiche Körper</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>Impetus scenes (*.json);;All files (*)</source>
        <translation>Impetus-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The default scene is shown instead.</source>
        <translation>Stattdessen wird die Standardszene gezeigt.</translation>
    </message>
    <message>
        <source>An empty scene is shown instead.</source>
        <translation>Stattdessen wird eine leere Szene gezeigt.</translation>
    </message>
    <message>
        <source>The current scene is unchanged.</source>
        <translation>Die aktuelle Szene bleibt unverändert.</translation>
    </message>
    <message>
        <source>Cannot open scene</source>
        <translation>Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>“%1” could not be opened. %2</source>
        <translation>„%1“ konnte nicht geöffnet werden. %2</translation>
    </message>
    <message numerus="yes">
        <source>…and %n more.</source>
        <translation>
            <numerusform>…und %n weiteres.</numerusform>
            <numerusform>…und %n weitere.</numerusform>
        </translation>
    </message>
    <message>
        <source>The simulation blew up</source>
        <translation>Die Simulation ist explodiert</translation>
    </message>
    <message>
        <source>Body “%1” got a position or velocity that is not a finite number by t = %2 s.</source>
        <translation>Körper „%1“ hat bis t = %2 s eine Position oder Geschwindigkeit bekommen, die keine endliche Zahl ist.</translation>
    </message>
    <message>
        <source>The run stopped at the last finite state. The time step is too large for the stiffest spring or the fastest motion in the scene. Press Reset (R) to go back to where you pressed Play, or Undo (Ctrl+Z); then try a smaller time step or a softer spring.</source>
        <translation>Der Lauf hat beim letzten endlichen Zustand angehalten. Der Zeitschritt ist zu groß für die steifste Feder oder die schnellste Bewegung der Szene. Mit Zurücksetzen (R) geht es zurück zum Start, oder mit Rückgängig (Strg+Z); dann einen kleineren Zeitschritt oder eine weichere Feder versuchen.</translation>
    </message>
    <message>
        <source>Cannot save scene</source>
        <translation>Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>The scene could not be saved to “%1”. Nothing was overwritten.</source>
        <translation>Die Szene konnte nicht in „%1“ gespeichert werden. Nichts wurde überschrieben.</translation>
    </message>
    <message>
        <source>Save Scene</source>
        <translation>Szene speichern</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved.</source>
        <translation>„%1“ hat Änderungen, die nicht gespeichert sind.</translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation>Vor dem Weitermachen speichern?</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Pause the simulation (Space)</source>
        <translation>Die Simulation anhalten (Leertaste)</translation>
    </message>
    <message>
        <source>Running %1 rigid and soft…</source>
        <translation>%1 läuft starr und weich…</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;th align=right&gt;t (s)&lt;/th&gt;&lt;th align=right&gt;distance (m)&lt;/th&gt;&lt;/tr&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;th align=right&gt;t (s)&lt;/th&gt;&lt;th align=right&gt;Abstand (m)&lt;/th&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source>Soft against rigid</source>
        <translation>Weich gegen starr</translation>
    </message>
    <message>
        <source>&lt;p&gt;How far the centre of mass of &lt;b&gt;%1&lt;/b&gt; run soft (%2 ellipses, %3 per m²) drifts from the same body run rigid, over the next %4 s:&lt;/p&gt;&lt;p&gt;RMS %5 m, largest %6 m at t = %7 s.&lt;/p&gt;%8</source>
        <translation>&lt;p&gt;Wie weit der Schwerpunkt von &lt;b&gt;%1&lt;/b&gt;, weich gerechnet (%2 Ellipsen, %3 pro m²), in den nächsten %4 s vom selben Körper, starr gerechnet, abweicht:&lt;/p&gt;&lt;p&gt;Effektivwert %5 m, höchstens %6 m bei t = %7 s.&lt;/p&gt;%8</translation>
    </message>
    <message>
        <source>%1 — %2 substeps per step</source>
        <translation>%1 — %2 Teilschritte pro Schritt</translation>
    </message>
    <message>
        <source>One step per step: the grids are stable at this time step.</source>
        <translation>Ein Teilschritt pro Schritt: Die Gitter sind bei diesem Zeitschritt stabil.</translation>
    </message>
    <message>
        <source>%1[*] — Impetus</source>
        <translation>%1[*] — Impetus</translation>
    </message>
    <message>
        <source>t = %L1 s</source>
        <translation>t = %L1 s</translation>
    </message>
    <message>
        <source>K = %L1 J  U = %L2 J  elastic = %L3 J</source>
        <translation>K = %L1 J  U = %L2 J  elastisch = %L3 J</translation>
    </message>
    <message>
        <source>E = %L1 J</source>
        <translation>E = %L1 J</translation>
    </message>
    <message>
        <source>p = (%L1, %L2) kg·m/s</source>
        <translation>p = (%L1; %L2) kg·m/s</translation>
    </message>
    <message>
        <source>Collisions: %L1</source>
        <translation>Stöße: %L1</translation>
    </message>
    <message>
        <source>%1: %L2/m² (auto)</source>
        <translation>%1: %L2/m² (automatisch)</translation>
    </message>
    <message>
        <source>%1: %L2/m²</source>
        <translation>%1: %L2/m²</translation>
    </message>
    <message>
        <source>Step Back</source>
        <translation>Schritt zurück</translation>
    </message>
    <message>
        <source>Go back one time step along the timeline (←)</source>
        <translation>Auf der Zeitleiste einen Zeitschritt zurückgehen (←)</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <source>Click two points, or drag: the distance in metres; snaps to body centres and corners</source>
        <translation>Zwei Punkte anklicken oder ziehen: der Abstand in Metern; rastet an Körpermitten und Ecken ein</translation>
    </message>
    <message>
        <source>Protractor</source>
        <translation>Winkelmesser</translation>
    </message>
    <message>
        <source>Click the vertex, then a point on each arm: the angle in degrees</source>
        <translation>Den Scheitel anklicken, dann einen Punkt auf jedem Schenkel: der Winkel in Grad</translation>
    </message>
    <message>
        <source>&amp;Vectors</source>
        <translation>&amp;Vektoren</translation>
    </message>
    <message>
        <source>&amp;Velocity</source>
        <translation>&amp;Geschwindigkeit</translation>
    </message>
    <message>
        <source>Arrows of each body&apos;s velocity</source>
        <translation>Pfeile der Geschwindigkeit jedes Körpers</translation>
    </message>
    <message>
        <source>&amp;Acceleration</source>
        <translation>&amp;Beschleunigung</translation>
    </message>
    <message>
        <source>Arrows of each body&apos;s acceleration, net force / mass</source>
        <translation>Pfeile der Beschleunigung jedes Körpers, Gesamtkraft / Masse</translation>
    </message>
    <message>
        <source>&amp;Net Force</source>
        <translation>Gesa&amp;mtkraft</translation>
    </message>
    <message>
        <source>Arrows of the net force on each body</source>
        <translation>Pfeile der Gesamtkraft auf jeden Körper</translation>
    </message>
    <message>
        <source>&amp;Force Parts</source>
        <translation>&amp;Einzelkräfte</translation>
    </message>
    <message>
        <source>Arrows of gravity, springs, drag, contact normal and friction forces and joint forces</source>
        <translation>Pfeile von Gewichtskraft, Federkräften, Luftwiderstand, Normal- und Reibungskräften der Kontakte und Gelenkkräften</translation>
    </message>
    <message>
        <source>&amp;Momentum</source>
        <translation>&amp;Impuls</translation>
    </message>
    <message>
        <source>Arrows of each body&apos;s momentum</source>
        <translation>Pfeile des Impulses jedes Körpers</translation>
    </message>
    <message>
        <source>&amp;Longer Arrows</source>
        <translation>&amp;Längere Pfeile</translation>
    </message>
    <message>
        <source>Double the length of every arrow (the legend gives the scale)</source>
        <translation>Alle Pfeile doppelt so lang zeichnen (die Legende nennt den Maßstab)</translation>
    </message>
    <message>
        <source>&amp;Shorter Arrows</source>
        <translation>&amp;Kürzere Pfeile</translation>
    </message>
    <message>
        <source>Halve the length of every arrow (the legend gives the scale)</source>
        <translation>Alle Pfeile halb so lang zeichnen (die Legende nennt den Maßstab)</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation>Sp&amp;uren</translation>
    </message>
    <message>
        <source>Draw the path of each body&apos;s centre of mass, with a dot every few steps</source>
        <translation>Die Bahn des Schwerpunkts jedes Körpers zeichnen, mit einem Punkt alle paar Schritte</translation>
    </message>
    <message>
        <source>Trail &amp;Dots Every</source>
        <translation>Spurpunk&amp;te alle</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n Schritt</numerusform>
            <numerusform>%n Schritte</numerusform>
        </translation>
    </message>
    <message>
        <source>Vectors and Trails for &amp;Selected Bodies Only</source>
        <translation>Vektoren und Spuren nur für &amp;ausgewählte Körper</translation>
    </message>
    <message>
        <source>Draw arrows and trails only for the bodies selected</source>
        <translation>Pfeile und Spuren nur für die ausgewählten Körper zeichnen</translation>
    </message>
    <message>
        <source>New &amp;Graph</source>
        <translation>&amp;Neues Diagramm</translation>
    </message>
    <message>
        <source>Plot a quantity of the selected body against time, or against another quantity</source>
        <translation>Eine Größe des ausgewählten Körpers über der Zeit oder über einer anderen Größe auftragen</translation>
    </message>
    <message>
        <source>Step back once</source>
        <translation>Einen Schritt zurück</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Sonde</translation>
    </message>
    <message>
        <source>Click a body to read its position, velocity, energies and collisions as it moves</source>
        <translation>Einen Körper anklicken, um Position, Geschwindigkeit, Energien und Stöße abzulesen, während er sich bewegt</translation>
    </message>
    <message>
        <source>E&amp;xplain</source>
        <translation>&amp;Erklären</translation>
    </message>
    <message>
        <source>&amp;Separating Axes</source>
        <translation>&amp;Trennende Achsen</translation>
    </message>
    <message>
        <source>Show how the collision test treats the two selected bodies, axis by axis (N: next, P: previous, Esc: close)</source>
        <translation>Zeigen, wie der Kollisionstest die beiden ausgewählten Körper behandelt, Achse für Achse (N: nächste, P: vorige, Esc: schließen)</translation>
    </message>
    <message>
        <source>Collision Inspector</source>
        <translation>Stoßinspektor</translation>
    </message>
    <message>
        <source>&amp;Collision Inspector</source>
        <translation>&amp;Stoßinspektor</translation>
    </message>
    <message>
        <source>List the collisions of the run; click one to see its impulse worked out</source>
        <translation>Die Stöße des Laufs auflisten; einen anklicken, um die Berechnung seines Kraftstoßes zu sehen</translation>
    </message>
    <message>
        <source>Energy &amp;Ledger</source>
        <translation>Energie&amp;bilanz</translation>
    </message>
    <message>
        <source>Chart where the energy goes: what each cause has taken out, stacked over time</source>
        <translation>Darstellen, wohin die Energie geht: was jede Ursache entnommen hat, über die Zeit gestapelt</translation>
    </message>
    <message>
        <source>Energy Ledger</source>
        <translation>Energiebilanz</translation>
    </message>
    <message>
        <source>Trace Point</source>
        <translation>Punkt verfolgen</translation>
    </message>
    <message>
        <source>Click a point on a body to draw the path it takes (a wheel&apos;s rim: a cycloid); click it again, or Esc, to stop</source>
        <translation>Klicken Sie auf einen Punkt eines Körpers, um seine Bahn zu zeichnen (am Rand eines Rades: eine Zykloide); erneut klicken oder Esc beendet es</translation>
    </message>
    <message>
        <source>At t = %1 s the solver let the centre of “%2” into “%3”; it was put back at the surface.</source>
        <translation>Bei t = %1 s hat die Simulation den Mittelpunkt von „%2“ in „%3“ eindringen lassen; er wurde an die Oberfläche zurückgesetzt.</translation>
    </message>
    <message numerus="yes">
        <source>%n more such body pair(s) in the same steps.</source>
        <translation>
            <numerusform>%n weiteres solches Körperpaar in denselben Schritten.</numerusform>
            <numerusform>%n weitere solche Körperpaare in denselben Schritten.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>impetus::view::PaceIndicator</name>
    <message>
        <source>Speed against real time</source>
        <translation>Tempo gegenüber Echtzeit</translation>
    </message>
    <message>
        <source>Computing a step…</source>
        <translation>Ein Schritt wird berechnet…</translation>
    </message>
    <message>
        <source>Running at %1× real time</source>
        <translation>Läuft mit %1× Echtzeit</translation>
    </message>
    <message>
        <source>Running at %1× real time (speed set to %2×)</source>
        <translation>Läuft mit %1× Echtzeit (eingestellt: %2×)</translation>
    </message>
    <message>
        <source>Simulated time runs at %1× real time, slower than the %2× asked for.</source>
        <translation>Die simulierte Zeit läuft mit %1× Echtzeit, langsamer als die gewünschten %2×.</translation>
    </message>
    <message>
        <source>Step (→) is computing one time step in the background. The canvas shows it when it is done; the window keeps working meanwhile.</source>
        <translation>Schritt (→) berechnet einen Zeitschritt im Hintergrund. Die Fläche zeigt ihn, sobald er fertig ist; das Fenster bleibt solange bedienbar.</translation>
    </message>
    <message>
        <source>No step has been computed yet; the first one has taken %1 s so far.</source>
        <translation>Noch ist kein Schritt berechnet; der erste hat bisher %1 s gedauert.</translation>
    </message>
    <message>
        <source>One step (%1 ms of simulated time) takes %2 ms to compute; at %3× it may take at most %4 ms.</source>
        <translation>Ein Schritt (%1 ms simulierte Zeit) braucht %2 ms Rechenzeit; bei %3× dürfte er höchstens %4 ms brauchen.</translation>
    </message>
    <message>
        <source>The last step took %1 ms to compute.</source>
        <translation>Die Berechnung des letzten Schritts dauerte %1 ms.</translation>
    </message>
    <message>
        <source>The steps being computed now have taken %1 s so far.</source>
        <translation>Die Schritte, die gerade berechnet werden, haben bisher %1 s gedauert.</translation>
    </message>
    <message>
        <source>The last step — bodies: %1, contacts: %2, impacts: %3. Solving the contacts and joints took %4 ms of its %5 ms.</source>
        <translation>Der letzte Schritt — Körper: %1, Kontakte: %2, Stöße: %3. Das Lösen der Kontakte und Gelenke dauerte %4 ms von seinen %5 ms.</translation>
    </message>
    <message>
        <source>Soft bodies split each step into %1 substeps. %2</source>
        <translation>Weiche Körper teilen jeden Schritt in %1 Teilschritte. %2</translation>
    </message>
    <message>
        <source>To make steps faster: use fewer bodies, or give soft bodies fewer ellipses per m².</source>
        <translation>Für schnellere Schritte: weniger Körper verwenden oder weichen Körpern weniger Ellipsen pro m² geben.</translation>
    </message>
    <message>
        <source>The steps themselves are fast enough: the computer was busy with something else for a moment.</source>
        <translation>Die Schritte selbst sind schnell genug: Der Computer war kurz mit etwas anderem beschäftigt.</translation>
    </message>
    <message>
        <source>To keep up: use fewer bodies, give soft bodies fewer ellipses per m², make the time step larger, or choose a lower speed.</source>
        <translation>Um mitzuhalten: weniger Körper verwenden, weichen Körpern weniger Ellipsen pro m² geben, den Zeitschritt vergrößern oder ein niedrigeres Tempo wählen.</translation>
    </message>
</context>
<context>
    <name>impetus::view::ProjectorMode</name>
    <message>
        <source>&amp;Projector Mode</source>
        <translation>&amp;Projektormodus</translation>
    </message>
    <message>
        <source>Full screen, large text and readouts, thick lines and strong contrast for a projector (F11)</source>
        <translation>Vollbild, große Schrift und Anzeigen, dicke Linien und starker Kontrast für den Projektor (F11)</translation>
    </message>
</context>
<context>
    <name>impetus::view::PropertyPane</name>
    <message>
        <source>Attributes</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Shown item</source>
        <translation>Gezeigtes Objekt</translation>
    </message>
    <message>
        <source>Selection note</source>
        <translation>Hinweis zur Auswahl</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>Unit: %1</source>
        <translation>Einheit: %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>World settings</source>
        <translation>Welteinstellungen</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>Change gravity</source>
        <translation>Schwerkraft ändern</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>Explicit Euler (euler)</source>
        <translation>Explizites Euler-Verfahren (euler)</translation>
    </message>
    <message>
        <source>Semi-implicit Euler (semi-implicit-euler)</source>
        <translation>Halbimplizites Euler-Verfahren (semi-implicit-euler)</translation>
    </message>
    <message>
        <source>Runge–Kutta 4 (rk4)</source>
        <translation>Runge-Kutta 4 (rk4)</translation>
    </message>
    <message>
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>Change time step</source>
        <translation>Zeitschritt ändern</translation>
    </message>
    <message>
        <source>Time step must be from %1 s to %2 s (got %3 s).</source>
        <translation>Der Zeitschritt muss zwischen %1 s und %2 s liegen (eingegeben: %3 s).</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>N·s/m</source>
        <translation>N·s/m</translation>
    </message>
    <message>
        <source>Change drag</source>
        <translation>Luftwiderstand ändern</translation>
    </message>
    <message>
        <source>Body attributes</source>
        <translation>Eigenschaften des Körpers</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Resize body</source>
        <translation>Größe des Körpers ändern</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Semi-axis x</source>
        <translation>Halbachse x</translation>
    </message>
    <message>
        <source>Semi-axis y</source>
        <translation>Halbachse y</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Ecken</translation>
    </message>
    <message>
        <source>Polygon vertices in the body&apos;s own frame, in metres</source>
        <translation>Ecken des Polygons im körpereigenen Koordinatensystem, in Metern</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>Add vertex</source>
        <translation>Ecke hinzufügen</translation>
    </message>
    <message>
        <source>Insert a vertex halfway along the edge after the current vertex</source>
        <translation>Eine Ecke in der Mitte der Kante nach der aktuellen Ecke einfügen</translation>
    </message>
    <message>
        <source>Remove vertex</source>
        <translation>Ecke entfernen</translation>
    </message>
    <message>
        <source>Remove the current vertex</source>
        <translation>Die aktuelle Ecke entfernen</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Move body</source>
        <translation>Körper verschieben</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>Rotate body</source>
        <translation>Körper drehen</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Change velocity</source>
        <translation>Geschwindigkeit ändern</translation>
    </message>
    <message>
        <source>Angular velocity</source>
        <translation>Winkelgeschwindigkeit</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>Change angular velocity</source>
        <translation>Winkelgeschwindigkeit ändern</translation>
    </message>
    <message>
        <source>Mass given as</source>
        <translation>Masse angegeben als</translation>
    </message>
    <message>
        <source>Choose whether you give the density or the mass; the other follows from the area</source>
        <translation>Wählen, ob die Dichte oder die Masse angegeben wird; das andere folgt aus der Fläche</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Dichte</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <source>kg/m²</source>
        <translation>kg/m²</translation>
    </message>
    <message>
        <source>Change density</source>
        <translation>Dichte ändern</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Change mass</source>
        <translation>Masse ändern</translation>
    </message>
    <message>
        <source>Moment of inertia</source>
        <translation>Trägheitsmoment</translation>
    </message>
    <message>
        <source>kg·m²</source>
        <translation>kg·m²</translation>
    </message>
    <message>
        <source>Restitution</source>
        <translation>Stoßzahl</translation>
    </message>
    <message>
        <source>(0–1)</source>
        <translation>(0–1)</translation>
    </message>
    <message>
        <source>Change restitution</source>
        <translation>Stoßzahl ändern</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <source>(≥ 0)</source>
        <translation>(≥ 0)</translation>
    </message>
    <message>
        <source>Change friction</source>
        <translation>Reibung ändern</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>Fest</translation>
    </message>
    <message>
        <source>A fixed body has infinite mass: it moves only with the velocity it is given</source>
        <translation>Ein fester Körper hat unendliche Masse: Er bewegt sich nur mit der Geschwindigkeit, die man ihm gibt</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <source>Soft body</source>
        <translation>Weicher Körper</translation>
    </message>
    <message>
        <source>Simulate the body as a grid of small ellipses joined by springs</source>
        <translation>Den Körper als Gitter kleiner, durch Federn verbundener Ellipsen simulieren</translation>
    </message>
    <message>
        <source>Ellipses per square metre</source>
        <translation>Ellipsen pro Quadratmeter</translation>
    </message>
    <message>
        <source>A number greater than 0, or “auto”</source>
        <translation>Eine Zahl größer als 0 oder „auto“</translation>
    </message>
    <message>
        <source>a number or “auto”</source>
        <translation>eine Zahl oder „auto“</translation>
    </message>
    <message>
        <source>Ellipses per m²</source>
        <translation>Ellipsen pro m²</translation>
    </message>
    <message>
        <source>1/m²</source>
        <translation>1/m²</translation>
    </message>
    <message>
        <source>Soft grid</source>
        <translation>Weiches Gitter</translation>
    </message>
    <message>
        <source>Soft stiffness</source>
        <translation>Steifigkeit (weich)</translation>
    </message>
    <message>
        <source>N/m</source>
        <translation>N/m</translation>
    </message>
    <message>
        <source>Change soft stiffness</source>
        <translation>Steifigkeit des weichen Körpers ändern</translation>
    </message>
    <message>
        <source>Soft damping</source>
        <translation>Dämpfung (weich)</translation>
    </message>
    <message>
        <source>Change soft damping</source>
        <translation>Dämpfung des weichen Körpers ändern</translation>
    </message>
    <message>
        <source>Spring attributes</source>
        <translation>Eigenschaften der Feder</translation>
    </message>
    <message>
        <source>Body A</source>
        <translation>Körper A</translation>
    </message>
    <message>
        <source>Anchor A</source>
        <translation>Anker A</translation>
    </message>
    <message>
        <source>Move spring end</source>
        <translation>Federende verschieben</translation>
    </message>
    <message>
        <source>Anchor A (body frame)</source>
        <translation>Anker A (Körperkoordinaten)</translation>
    </message>
    <message>
        <source>Body B</source>
        <translation>Körper B</translation>
    </message>
    <message>
        <source>Anchor B</source>
        <translation>Anker B</translation>
    </message>
    <message>
        <source>Stiffness</source>
        <translation>Federkonstante</translation>
    </message>
    <message>
        <source>Change spring stiffness</source>
        <translation>Federkonstante ändern</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>Change spring damping</source>
        <translation>Dämpfung der Feder ändern</translation>
    </message>
    <message>
        <source>Rest length</source>
        <translation>Ruhelänge</translation>
    </message>
    <message>
        <source>Change rest length</source>
        <translation>Ruhelänge ändern</translation>
    </message>
    <message>
        <source>Joint attributes</source>
        <translation>Eigenschaften des Gelenks</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Hinge</source>
        <translation>Drehpunkt</translation>
    </message>
    <message>
        <source>Move hinge</source>
        <translation>Drehpunkt verschieben</translation>
    </message>
    <message>
        <source>Move rod end</source>
        <translation>Stangenende verschieben</translation>
    </message>
    <message>
        <source>Hinge (world point)</source>
        <translation>Drehpunkt (Weltpunkt)</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>The size or density is too extreme to simulate (mass %1 kg, moment of inertia %2 kg·m²).</source>
        <translation>Größe oder Dichte sind zu extrem für die Simulation (Masse %1 kg, Trägheitsmoment %2 kg·m²).</translation>
    </message>
    <message>
        <source>A rod needs two different ends: both anchors are at the same point.</source>
        <translation>Eine Stange braucht zwei verschiedene Enden: Beide Anker liegen am selben Punkt.</translation>
    </message>
    <message>
        <source>Name: a body needs a name.</source>
        <translation>Name: Ein Körper braucht einen Namen.</translation>
    </message>
    <message>
        <source>Name: another body is already called “%1”; names must be unique.</source>
        <translation>Name: Ein anderer Körper heißt schon „%1“; Namen müssen eindeutig sein.</translation>
    </message>
    <message>
        <source>Rename body</source>
        <translation>Körper umbenennen</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>%1: “%2” is neither a number nor “auto”.</source>
        <translation>%1: „%2“ ist weder eine Zahl noch „auto“.</translation>
    </message>
    <message>
        <source>%1 must be a number greater than 0, or “auto” (got %2).</source>
        <translation>%1 muss eine Zahl größer als 0 oder „auto“ sein (eingegeben: %2).</translation>
    </message>
    <message>
        <source>Change soft density</source>
        <translation>Ellipsendichte ändern</translation>
    </message>
    <message>
        <source>Vertex %1 %2</source>
        <translation>Ecke %1 %2</translation>
    </message>
    <message>
        <source>Move vertex</source>
        <translation>Ecke verschieben</translation>
    </message>
    <message>
        <source>Vertices: choose the vertex to remove in the table first.</source>
        <translation>Ecken: zuerst die zu entfernende Ecke in der Tabelle wählen.</translation>
    </message>
    <message>
        <source>Vertices: the shape is refused: %1.</source>
        <translation>Ecken: Die Form wird abgelehnt: %1.</translation>
    </message>
    <message>
        <source>Give mass instead of density</source>
        <translation>Masse statt Dichte angeben</translation>
    </message>
    <message>
        <source>Give density instead of mass</source>
        <translation>Dichte statt Masse angeben</translation>
    </message>
    <message>
        <source>Change integrator</source>
        <translation>Integrator ändern</translation>
    </message>
    <message>
        <source>Fix body</source>
        <translation>Körper festsetzen</translation>
    </message>
    <message>
        <source>Free body</source>
        <translation>Körper freigeben</translation>
    </message>
    <message>
        <source>Turn on soft mode</source>
        <translation>Weichen Modus einschalten</translation>
    </message>
    <message>
        <source>Turn off soft mode</source>
        <translation>Weichen Modus ausschalten</translation>
    </message>
    <message>
        <source>Body Colour</source>
        <translation>Farbe des Körpers</translation>
    </message>
    <message>
        <source>Change colour</source>
        <translation>Farbe ändern</translation>
    </message>
    <message>
        <source>(world)</source>
        <translation>(Welt)</translation>
    </message>
    <message numerus="yes">
        <source>%n items selected; the pane shows the first.</source>
        <translation>
            <numerusform>%n Objekt ausgewählt; die Leiste zeigt das erste.</numerusform>
            <numerusform>%n Objekte ausgewählt; die Leiste zeigt das erste.</numerusform>
        </translation>
    </message>
    <message>
        <source>World</source>
        <translation>Welt</translation>
    </message>
    <message>
        <source>Body “%1”</source>
        <translation>Körper „%1“</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <source>Ellipse</source>
        <translation>Ellipse</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Rechteck</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polygon</translation>
    </message>
    <message>
        <source>Current colour %1; press to choose another</source>
        <translation>Aktuelle Farbe %1; klicken, um eine andere zu wählen</translation>
    </message>
    <message>
        <source>Vertex %1 %2 = %3 m</source>
        <translation>Ecke %1 %2 = %3 m</translation>
    </message>
    <message>
        <source>Spring %1</source>
        <translation>Feder %1</translation>
    </message>
    <message>
        <source>Anchor B (body frame)</source>
        <translation>Anker B (Körperkoordinaten)</translation>
    </message>
    <message>
        <source>Anchor B (world point)</source>
        <translation>Anker B (Weltpunkt)</translation>
    </message>
    <message>
        <source>Pin joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
    <message>
        <source>Rod joint %1</source>
        <translation>Stange %1</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Rod</source>
        <translation>Stange</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number.</source>
        <translation>%1: „%2“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>%1 must be a finite number (got %2).</source>
        <translation>%1 muss eine endliche Zahl sein (eingegeben: %2).</translation>
    </message>
    <message>
        <source>%1 must be greater than 0 (got %2).</source>
        <translation>%1 muss größer als 0 sein (eingegeben: %2).</translation>
    </message>
    <message>
        <source>%1 must be 0 or greater (got %2).</source>
        <translation>%1 muss 0 oder größer sein (eingegeben: %2).</translation>
    </message>
    <message>
        <source>%1 must be between 0 and 1 (got %2).</source>
        <translation>%1 muss zwischen 0 und 1 liegen (eingegeben: %2).</translation>
    </message>
    <message>
        <source>%L1 ellipses at %L2 per m², chosen by “auto” on this computer</source>
        <translation>%L1 Ellipsen bei %L2 pro m², von „auto“ auf diesem Computer gewählt</translation>
    </message>
    <message>
        <source>%L1 ellipses at %L2 per m²</source>
        <translation>%L1 Ellipsen bei %L2 pro m²</translation>
    </message>
    <message>
        <source>Lock note</source>
        <translation>Sperrhinweis</translation>
    </message>
    <message>
        <source>Soft damping ratio ζ</source>
        <translation>Dämpfungsgrad ζ (weich)</translation>
    </message>
    <message>
        <source>Change soft damping ratio</source>
        <translation>Dämpfungsgrad des weichen Körpers ändern</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
    <message>
        <source>Show vectors</source>
        <translation>Vektoren zeigen</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>Net force</source>
        <translation>Gesamtkraft</translation>
    </message>
    <message>
        <source>Force parts</source>
        <translation>Einzelkräfte</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Impuls</translation>
    </message>
    <message>
        <source>Show %1 arrows of this body</source>
        <translation>Pfeile dieses Körpers zeigen: %1</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Use a time step of %1 ms</source>
        <translation>Zeitschritt von %1 ms verwenden</translation>
    </message>
    <message>
        <source>Use the time step that holds this spring</source>
        <translation>Den Zeitschritt verwenden, den diese Feder verträgt</translation>
    </message>
</context>
<context>
    <name>impetus::view::SatExplainer</name>
    <message>
        <source>Separating axes: A = %1 (blue), B = %2 (orange)</source>
        <translation>Trennende Achsen: A = %1 (blau), B = %2 (orange)</translation>
    </message>
    <message>
        <source>Convex pieces: %1 of A and %2 of B (pair %3 of %4)</source>
        <translation>Konvexe Teile: %1 von A und %2 von B (Paar %3 von %4)</translation>
    </message>
    <message>
        <source>Method: SAT over the face normals of both polygons: %1 candidate axes, %2 tested.</source>
        <translation>Verfahren: Trennachsentest (SAT) über die Seitennormalen beider Polygone: %1 mögliche Achsen, %2 geprüft.</translation>
    </message>
    <message>
        <source>Method: the polygon&apos;s face normals, then the feature of the polygon closest to the circle&apos;s centre (a face or a corner): a circle has no faces of its own.</source>
        <translation>Verfahren: die Seitennormalen des Polygons, dann das Element des Polygons, das dem Kreismittelpunkt am nächsten liegt (eine Seite oder eine Ecke): Ein Kreis hat selbst keine Seiten.</translation>
    </message>
    <message>
        <source>Method: two circles need a single axis, the line through their centres.</source>
        <translation>Verfahren: Zwei Kreise brauchen nur eine Achse, die Gerade durch ihre Mittelpunkte.</translation>
    </message>
    <message>
        <source>Method: GJK and EPA. An ellipse has no faces, so there are no axes to test: GJK finds the distance between the shapes, and when they overlap EPA finds the depth and the direction of least penetration (to 0.001 mm).</source>
        <translation>Verfahren: GJK und EPA. Eine Ellipse hat keine Seiten, also gibt es keine Achsen zu prüfen: GJK findet den Abstand der Formen, und wenn sie sich überlappen, findet EPA die Tiefe und die Richtung der geringsten Eindringung (auf 0,001 mm genau).</translation>
    </message>
    <message>
        <source>Result: normal %1, depth %2 mm at %3.</source>
        <translation>Ergebnis: Normale %1, Tiefe %2 mm bei %3.</translation>
    </message>
    <message>
        <source>Result: the shapes are apart.</source>
        <translation>Ergebnis: Die Formen sind getrennt.</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>normal of face %1 of %2</source>
        <translation>Normale der Seite %1 von %2</translation>
    </message>
    <message>
        <source>from corner %1 of %2 to the circle&apos;s centre</source>
        <translation>von Ecke %1 von %2 zum Kreismittelpunkt</translation>
    </message>
    <message>
        <source>line of centres, from A to B</source>
        <translation>Verbindungslinie der Mittelpunkte, von A nach B</translation>
    </message>
    <message>
        <source>Axis %1 of %2: %3, direction %4</source>
        <translation>Achse %1 von %2: %3, Richtung %4</translation>
    </message>
    <message>
        <source>Projections: %1 from %2 to %3 mm, %4 from %5 to %6 mm</source>
        <translation>Projektionen: %1 von %2 bis %3 mm, %4 von %5 bis %6 mm</translation>
    </message>
    <message>
        <source>Overlap on this axis: %1 mm</source>
        <translation>Überlappung auf dieser Achse: %1 mm</translation>
    </message>
    <message>
        <source>Gap on this axis: %1 mm</source>
        <translation>Abstand auf dieser Achse: %1 mm</translation>
    </message>
    <message>
        <source>This axis separates the shapes: no contact. The search stops here (%1 of %2 axes tested).</source>
        <translation>Diese Achse trennt die Formen: kein Kontakt. Die Suche endet hier (%1 von %2 Achsen geprüft).</translation>
    </message>
    <message>
        <source>This is the axis of least overlap.</source>
        <translation>Dies ist die Achse der geringsten Überlappung.</translation>
    </message>
    <message>
        <source>Separated: axis %1 leaves a gap of %2 mm, so the pair is not in contact.</source>
        <translation>Getrennt: Achse %1 lässt einen Abstand von %2 mm, also berührt sich das Paar nicht.</translation>
    </message>
    <message>
        <source>Least overlap: axis %1 (%2), %3 mm</source>
        <translation>Geringste Überlappung: Achse %1 (%2), %3 mm</translation>
    </message>
    <message>
        <source>B&apos;s best face is better by less than the tolerance, so A&apos;s face stays the reference: resting stacks do not swap faces on rounding noise.</source>
        <translation>Die beste Seite von B ist um weniger als die Toleranz besser, daher bleibt die Seite von A die Referenz: Ruhende Stapel wechseln ihre Seiten nicht wegen Rundungsrauschen.</translation>
    </message>
    <message>
        <source>Minimum translation vector: %1 mm along %2 (moves B off A)</source>
        <translation>Minimaler Verschiebungsvektor: %1 mm entlang %2 (schiebt B von A weg)</translation>
    </message>
    <message>
        <source>Reference face (green): face %1 of %2; incident face (purple): face %3 of %4</source>
        <translation>Referenzseite (grün): Seite %1 von %2; einfallende Seite (lila): Seite %3 von %4</translation>
    </message>
    <message>
        <source>The incident face lies beyond the reference face&apos;s ends (corner to corner): one point.</source>
        <translation>Die einfallende Seite liegt jenseits der Enden der Referenzseite (Ecke an Ecke): ein Punkt.</translation>
    </message>
    <message>
        <source>Clipped to the reference face&apos;s sides: %1 points; kept (touching): %2</source>
        <translation>An den Seitengrenzen der Referenzseite abgeschnitten: %1 Punkte; behalten (berührend): %2</translation>
    </message>
    <message>
        <source>Contact point %1: %2 m, separation %3 mm</source>
        <translation>Kontaktpunkt %1: %2 m, Abstand %3 mm</translation>
    </message>
    <message>
        <source>N: next axis   P: previous   Esc: close</source>
        <translation>N: nächste Achse   P: vorige   Esc: schließen</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <extracomment>A point or a direction: its x and y. Where the decimal separator is a comma, separate them with a semicolon: (0,600; 0,800).</extracomment>
        <translation>(%1; %2)</translation>
    </message>
</context>
<context>
    <name>impetus::view::SceneDocument</name>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
</context>
<context>
    <name>impetus::view::TimelineBar</name>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>Time along the run</source>
        <translation>Zeit im Lauf</translation>
    </message>
    <message>
        <source>Drag to go back to any moment of the run; Play goes on from there</source>
        <translation>Ziehen, um zu einem beliebigen Moment des Laufs zurückzugehen; Start macht von dort aus weiter</translation>
    </message>
    <message>
        <source>Time shown</source>
        <translation>Angezeigte Zeit</translation>
    </message>
    <message>
        <source>t = %1 s of %2 s</source>
        <translation>t = %1 s von %2 s</translation>
    </message>
</context>
</TS>
